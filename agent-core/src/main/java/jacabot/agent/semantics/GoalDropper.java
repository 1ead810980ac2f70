package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * {@code .succeed_goal(g)} and {@code .fail_goal(g)}: end goal g wherever it is pursued; and
 * goals whose goal condition ({@code <:}) holds, ended as achieved (Jason's ClrSatInt).
 */
public final class GoalDropper {
    /** Whether the dropped goal counts as achieved or as failed. */
    public enum Mode { SUCCEED, FAIL }

    private final Agent ag;
    private final Mode mode;
    /** The goal, or null when ending the goals whose condition holds. */
    private final Literal goal;
    private final Trigger trigger;
    private final Predicate<IntendedMeans> intended;

    private static final Literal DROP_BY_FAIL_GOAL = Literal.atom("drop_by_fail_goal");

    /** Goal states of a goal dropped while still an event (Jason's .succeed_goal/.fail_goal). */
    private void notifyEvent(Trigger t) {
        if (mode == Mode.SUCCEED) {
            ag.goalStates().finished(t, GoalStates.State.achieved);
        } else {
            ag.goalStates().post(t, GoalStates.State.failed, DROP_BY_FAIL_GOAL);
        }
    }

    private final String error, message;

    /** As Jason's {@code .fail_goal}, the failure event carries no error annotation. */
    public GoalDropper(Agent ag, Mode mode, Literal goal) {
        this(ag, mode, goal, null, null);
    }

    /** A dropper whose failure event carries {@code error(Error)} and {@code error_msg(Message)} (a null error: none). */
    public GoalDropper(Agent ag, Mode mode, Literal goal, String error, String message) {
        this.ag = ag;
        this.mode = mode;
        this.goal = goal;
        this.trigger = goal == null ? null : new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, goal);
        this.intended = goal == null ? null : im -> im.trigger().isAchieveGoal() && im.trigger().isAddition()
                && ag.newUnifier().unifies(goal, im.trigger().literal());
        this.error = error;
        this.message = message;
    }

    private GoalDropper(Agent ag, Predicate<IntendedMeans> intended) {
        this.ag = ag;
        this.mode = Mode.SUCCEED;
        this.goal = null;
        this.trigger = null;
        this.intended = intended;
        this.error = null;
        this.message = null;
    }

    /**
     * Ends, as achieved, the goals whose goal condition holds, in every intention (Jason's
     * ClrSatInt, at the start of each cycle's act stage while an intention has one): the intended
     * means down to the lowest such goal are dropped, and the intention goes on below it.
     */
    static void dropSatisfied(Agent ag) {
        int[] tested = {0};
        new GoalDropper(ag, im -> {
            if (im.hasGoalCondition() && !Literal.FALSE.equals(im.plan().goalCondition())) {
                tested[0]++;
            }
            return im.goalConditionHolds(ag);
        }).drop();
        if (tested[0] == 0) {
            ag.circumstance().resetIntentionsWithGoalCondition(); // none left (or only `false`): stop testing
        }
    }

    /** {@return whether a {@code ^!g} plan is relevant for the goal of this trigger} */
    private boolean hasGoalStatePlan(Trigger goal) {
        Trigger meta = new Trigger(Trigger.Op.GOAL_STATE, goal.type(), goal.literal());
        for (Plan p : ag.planLibrary().candidates(meta)) {
            // the state annotations are the meta event's, not the goal's
            if (p.trigger().literal() instanceof Literal pl && ag.newUnifier().unifies(pl.withoutAnnots(), goal.literal())) {
                return true;
            }
        }
        return false;
    }

    public void drop() {
        Circumstance c = ag.circumstance();
        for (Event e : c.eventList()) {
            Intention i = e.intention();
            int r = dropIn(i);
            if (r > 0) {
                c.removeEvent(e);
                if (r == 1) {
                    c.addRunningIntention(i);
                }
            } else if (goal != null && e.trigger().isAchieveGoal() && e.trigger().isAddition()
                    && ag.newUnifier().unifies(goal, i == null ? e.trigger().literal() : i.peek() == null
                            ? e.trigger().literal() : i.peek().unifier().apply(e.trigger().literal()))) {
                c.removeEvent(e);
                notifyEvent(e.trigger());
                // as Jason: a goal not yet handled becomes its failure event (no error
                // annotation), in the same intention, when a -!g plan is relevant
                Trigger failTrigger = mode == Mode.FAIL
                        ? new Trigger(Trigger.Op.DEL, Trigger.Type.ACHIEVE, e.trigger().literal()) : null;
                if (failTrigger != null && (i == null || !i.isFinished()) && ag.planLibrary().hasCandidate(failTrigger)) {
                    c.addEvent(new Event(failTrigger, i));
                } else if (failTrigger != null && i == null && hasGoalStatePlan(e.trigger())) {
                    // a !!g with no -!g plan is dropped silently, unless a ^!g plan follows the
                    // goal's states: then Jason still posts -!g, which finds no plan and is
                    // discarded with two warnings (jason-oracle/42)
                    c.addEvent(new Event(failTrigger, null));
                } else if (i != null && !i.isFinished()) {
                    if (mode == Mode.SUCCEED) {
                        ag.cycle().removeActionReQueue(i);
                    } else {
                        ag.failIntention(i, "ia_failed", "");
                    }
                }
            }
        }
        for (Intention i : c.runningIntentions()) {
            if (dropIn(i) > 1) {
                c.removeRunningIntention(i);
            }
        }
        Intention si = c.selectedIntention();
        if (si != null) {
            int r = dropIn(si);
            if (r > 1 || (r == 1 && mode == Mode.FAIL)) {
                if (r == 2 && !si.isFinished()) {
                    // Jason goes past the step that posted the dropped goal (its requeue after the
                    // internal action), so the failure plan, once ended, ends the goals below it
                    si.peek().removeCurrentStep();
                }
                if (r == 2) {
                    ag.cycle().holdForFailureEvent(si);
                } else {
                    ag.holdSelectedIntention();
                }
            }
        }
        for (Intention i : c.pendingActionIntentions()) {
            int r = dropIn(i);
            if (r > 0) {
                c.removePendingAction(i.id());
                if (r == 1) {
                    c.addRunningIntention(i);
                }
            }
        }
        for (Map.Entry<String, Circumstance.Pending> p : c.pendingIntentions().entrySet()) {
            Intention i = p.getValue().intention();
            int r = dropIn(i);
            if (r > 0) {
                c.removePendingIntention(p.getKey());
                if (r == 1) {
                    c.addRunningIntention(i);
                }
            }
        }
    }

    /**
     * {@return 0 when the intention does not pursue the goal, 1 when it goes on, 2 when a failure
     * event was generated for it, 3 when it ended}
     */
    private int dropIn(Intention i) {
        if (i == null) {
            return 0;
        }
        IntendedMeans im = i.dropGoal(intended);
        if (im == null) {
            return 0;
        }
        GoalStates gs = ag.goalStates();
        Trigger dropped = GoalStates.of(im);
        if (mode == Mode.SUCCEED) {
            gs.finished(dropped, GoalStates.State.achieved);
            if (!i.isFinished()) {
                if (ag.circumstance().selectedIntention() != i) {
                    i.peek().removeCurrentStep();
                }
                ag.clearIntention(i);
                return 1;
            }
            return 3;
        }
        gs.post(dropped, GoalStates.State.failed, DROP_BY_FAIL_GOAL);
        Event failEvent = ag.failureEventFor(i, trigger);
        if (failEvent == null) {
            gs.finished(dropped, null);
        }
        if (failEvent != null) {
            if (error != null) {
                Literal lit = (Literal) failEvent.trigger().literal();
                List<Term> annots = List.of(Literal.of("error", Literal.atom(error)),
                        Literal.of("error_msg", new StringTerm(message)));
                failEvent = new Event(failEvent.trigger().withLiteral(lit.addAnnots(annots)), i);
            }
            ag.circumstance().addEvent(failEvent);
            return 2;
        }
        return 3;
    }
}
