package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.List;

/**
 * Goal states as Jason's goal listener for meta-events: each change of a goal's state posts
 * {@code ^!g[state(S)[reason(R)]]} at the start of the next cycle, ahead of the other events,
 * when some plan listens to it.
 */
public final class GoalStates {
    /** Jason's {@code GoalListener.GoalStates}. */
    public enum State { pending, executing, suspended, resumed, waiting, achieved, dropped, failed, finished }

    private final Agent ag;

    GoalStates(Agent ag) {
        this.ag = ag;
    }

    /**
     * {@return whether some plan listens to goal states} Without one, callers skip applying the
     * goal's unifier for a post that would do nothing (a subgoal finishes every few cycles).
     */
    boolean listening() {
        return ag.planLibrary().hasGoalStatePlans();
    }

    /** Posts a state of a goal; triggers that are not goals (or are meta-events) post nothing. */
    public void post(Trigger goal, State state, Term reason) {
        if (!goal.isGoal() || goal.op() == Trigger.Op.GOAL_STATE || !(goal.literal() instanceof Literal lit)
                || !ag.planLibrary().hasGoalStatePlans()) {
            return;
        }
        ag.runAtBeginOfNextCycle(() -> {
            Literal annot = new Literal("state", List.of(Literal.atom(state.name())),
                    List.of(Literal.of("reason", reason == null ? new StringTerm("") : reason)), false);
            Trigger meta = new Trigger(Trigger.Op.GOAL_STATE, goal.type(), lit.addAnnot(annot));
            if (ag.planLibrary().hasCandidate(meta)) {
                ag.circumstance().insertMetaEvent(new Event(meta, null));
            }
        });
    }

    /** A goal ended: its result (if any), then {@code finished}. */
    public void finished(Trigger goal, State result) {
        if (result != null) {
            post(goal, result, null);
        }
        post(goal, State.finished, null);
    }

    /** {@return the trigger of an intended means with its bindings} */
    public static Trigger of(IntendedMeans im) {
        return im.trigger().withLiteral(im.unifier().apply(im.trigger().literal()));
    }

    /** A state of the goal on top of an intention, when that is a goal being achieved. */
    public void ofTop(Intention i, State state, Term reason) {
        if (!listening()) {
            return; // post would do nothing: the goal's unifier need not be applied (every .wait comes here twice)
        }
        IntendedMeans im = i == null ? null : i.peek();
        if (im != null && im.trigger().isAddition()) {
            post(of(im), state, reason);
        }
    }

    /** An intention was dropped: each of its goals is {@code dropped} and {@code finished}. */
    void dropped(Intention i) {
        for (IntendedMeans im : i) {
            if (im.trigger().isAddition() && im.trigger().isGoal()) {
                finished(of(im), State.dropped);
            }
        }
    }

    /** An event was added: a new goal is {@code pending} (as Jason, posted as an achievement goal). */
    void eventAdded(Event e) {
        Trigger t = e.trigger();
        if (listening() && t.isAddition() && t.isGoal() && t.op() != Trigger.Op.GOAL_STATE) {
            post(new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, t.literal()), State.pending, null);
        }
    }
}
