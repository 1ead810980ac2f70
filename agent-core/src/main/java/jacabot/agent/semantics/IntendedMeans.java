package jacabot.agent.semantics;

import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A plan instance on an intention's stack: the plan, the event it handles, its unifier and the
 * steps still to run.
 */
public final class IntendedMeans {
    private final Plan plan;
    private final Trigger trigger;
    /** The plan's {@code atomic} option, looked up once: the intention asks at every push and pop. */
    private final boolean atomic;
    private Unifier unif;
    private StepList steps;
    /** Variables of the current step renamed apart when it posted an event (caller side). */
    private Map<Var, Var> renamedVars;
    /** The last loop turn's steps, made for the loop step's list {@code loopAt} and body {@code loopBody}. */
    private StepList loopAt;
    private List<BodyStep> loopBody;
    private StepList loopTurn;
    /** The unifier the plan was chosen with, kept for its goal condition (Jason's triggerUnif), or null. */
    private final Unifier chosenWith;

    /** An intended means whose plan's steps and atomic option are known (see {@link Start}). */
    private IntendedMeans(Plan plan, Trigger trigger, Unifier unif, StepList steps, boolean atomic) {
        this.plan = plan;
        this.atomic = atomic;
        this.trigger = trigger;
        this.unif = unif;
        this.steps = steps;
        this.chosenWith = plan.goalCondition() == null ? null : unif.copy();
    }

    /** {@return whether the plan has a goal condition ({@code <:})} */
    public boolean hasGoalCondition() {
        return chosenWith != null;
    }

    /**
     * {@return whether the plan's goal condition holds, solved in the unifier the plan was chosen
     * with (as Jason's), so that later bindings of the body do not count; false without one}
     */
    boolean goalConditionHolds(Agent ag) {
        return chosenWith != null && ag.solver().believes(plan.goalCondition(), chosenWith.copy());
    }

    /**
     * Makes intended means, keeping each plan's first step list: the steps are an immutable list,
     * so every intended means of a plan may start with the same one. A robot's agent adopts a few
     * plans in turn every control step; each new list was a node per step made, and printed anew
     * by the mind probe (which keeps a list's text by object).
     */
    static final class Start {
        /** Plans whose steps are kept at most (a library reloaded many times); past this it starts anew. */
        static final int KEPT = 4096;
        private final Map<Plan, StepList> steps = new IdentityHashMap<>();
        private Plan plan;
        private StepList last;
        private boolean atomic;

        IntendedMeans of(Plan p, Trigger trigger, Unifier unif) {
            if (p != plan) {
                last = steps.get(p);
                if (last == null) {
                    if (steps.size() >= KEPT) {
                        steps.clear();
                    }
                    last = StepList.of(p.body().steps(), null);
                    steps.put(p, last);
                }
                atomic = p.isAtomic();
                plan = p;
            }
            return new IntendedMeans(p, trigger, unif, last, atomic);
        }
    }

    /** {@return a copy with its own unifier, at the same step (for an intention that forks)} */
    IntendedMeans copy() {
        IntendedMeans c = new IntendedMeans(plan, trigger, unif.copy(), steps, atomic);
        c.renamedVars = renamedVars == null ? null : new LinkedHashMap<>(renamedVars);
        return c;
    }

    public Plan plan() {
        return plan;
    }

    /** {@return whether the plan is atomic} */
    public boolean isAtomic() {
        return atomic;
    }

    /** {@return the event's trigger, with the plan's unifier applied when asked} */
    public Trigger trigger() {
        return trigger;
    }

    public Unifier unifier() {
        return unif;
    }

    public void setUnifier(Unifier u) {
        this.unif = u;
    }

    public boolean isFinished() {
        return steps == null;
    }

    /** {@return the step to run next, or null} */
    public BodyStep currentStep() {
        return steps == null ? null : steps.head;
    }

    /**
     * {@return the steps still to run, or null: an immutable list, so the same object for as long
     * as they are the same steps (the mind probe prints them again only when it changes)}
     */
    public StepList steps() {
        return steps;
    }

    /** {@return the steps still to run, as Jason prints a plan body: {@code a; b; c}} */
    public String remainingBody() {
        var sb = new StringBuilder();
        for (StepList s = steps; s != null; s = s.next) {
            if (sb.length() > 0) {
                sb.append("; ");
            }
            sb.append(s.head);
        }
        return sb.toString();
    }

    /** {@return the steps still to run} */
    public List<BodyStep> remainingSteps() {
        var out = new ArrayList<BodyStep>();
        for (StepList s = steps; s != null; s = s.next) {
            out.add(s.head);
        }
        return out;
    }

    /** {@return whether the current step is the last one} */
    public boolean isLastStep() {
        return steps != null && steps.next == null;
    }

    public void removeCurrentStep() {
        if (steps != null) {
            steps = steps.next;
        }
    }

    /** Places steps right after the current step (how if/while/for unfold). */
    public void insertAfterCurrent(List<BodyStep> more) {
        if (steps == null) {
            steps = StepList.of(more, null);
        } else {
            steps = new StepList(steps.head, StepList.of(more, steps.next));
        }
    }

    /** Places steps and then one more right after the current step (a loop's body and the loop again). */
    public void insertAfterCurrent(List<BodyStep> more, BodyStep then) {
        if (steps == null) {
            insertAfterCurrent(List.of(then));
            insertAfterCurrent(more);
        } else if (steps.head == then) {
            // a loop's later turns: the loop step followed by what follows it is the current list
            // itself, and the turn's list is the same as the last turn's (the lists never change)
            if (loopAt != steps || loopBody != more) {
                loopAt = steps;
                loopBody = more;
                loopTurn = new StepList(then, StepList.of(more, steps));
            }
            steps = loopTurn;
        } else {
            steps = new StepList(steps.head, StepList.of(more, new StepList(then, steps.next)));
        }
    }

    /** Replaces the current step by several (a fork's branch and its join). */
    public void replaceCurrentStep(List<BodyStep> with) {
        steps = StepList.of(with, steps == null ? null : steps.next);
    }

    /** Replaces the current step (e.g. a loop step with its saved state). */
    public void replaceCurrentStep(BodyStep step) {
        steps = new StepList(step, steps == null ? null : steps.next);
    }

    /** {@return the caller-side renaming of the current step's variables, or null} */
    Map<Var, Var> renamedVars() {
        return renamedVars;
    }

    void setRenamedVars(Map<Var, Var> m) {
        renamedVars = m;
    }

    void clearRenamedVars() {
        renamedVars = null;
    }

    /**
     * {@return the fresh variable the current step gave the free variable {@code w} for its event,
     * or null} The step's variables were renamed as they stand in the plan (X, not the variable at
     * the end of X's chain, as Jason applies), so each is looked up by where its chain ends.
     */
    Var renamedVarFor(Var w) {
        if (renamedVars == null) {
            return null;
        }
        for (Map.Entry<Var, Var> r : renamedVars.entrySet()) {
            if (unifier().deref(r.getKey()).equals(w)) {
                return r.getValue();
            }
        }
        return null;
    }

    Map<Var, Var> renamedVarsOrNew() {
        if (renamedVars == null) {
            renamedVars = new LinkedHashMap<>();
        }
        return renamedVars;
    }

    @Override
    public String toString() {
        return plan.label() == null ? trigger.toString() : trigger + " (@" + plan.label().functor() + ")";
    }
}
