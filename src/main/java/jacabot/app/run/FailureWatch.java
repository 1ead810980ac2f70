package jacabot.app.run;

import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.PlanLibrary;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Whether an agent has failed at its job, so that a run can end at once with one line saying why
 * instead of going on for its whole duration with a robot that does nothing. Its failures:
 * <ul>
 * <li>no plan for an initial goal ({@code !start}): nothing runs after the first reasoning;</li>
 * <li>the system stopped ({@code .stopMAS}) before the run's end, e.g. by the initial phase's
 *     {@code -!start} after an action that does not exist;</li>
 * <li>a failure storm: one goal failing with the same error at least {@link #STORM_PER_SECOND}
 *     times in one simulated second (a failure plan that re-posts the goal at once, every cycle);</li>
 * <li>a failure no plan handles, of an initial goal's intention (the agent dropped what it was
 *     started for) or of an action that does not exist (an unknown artifact operation);</li>
 * <li>reasoning that runs away: the agent still busy after the run's cap of reasoning cycles in one
 *     control step ({@link SteppedPlatform#reason}), so simulated time would not move on.</li>
 * </ul>
 * Fed on the agent's thread by the plan listener ({@link #planSelected}); the run driver asks
 * {@link #verdict} after each control step.
 */
public final class FailureWatch {
    /**
     * Failures of one goal with one error in one simulated second that make a storm. A recovery
     * that retries after a wait fails a few times a second (the agents' polls wait 100 ms); a storm
     * fails every reasoning cycle, thousands of times per control step.
     */
    public static final int STORM_PER_SECOND = 1000;

    private final Set<String> initialGoals = new LinkedHashSet<>();
    /** The goals a plan was chosen for, until {@link #firstReasoningDone}, their only reader: no key is made after it. */
    private final Set<String> started = new LinkedHashSet<>();
    private boolean firstReasoningDone;
    private final Map<String, Integer> counts = new HashMap<>();
    private long second = -1;
    private Literal lastFailure;
    private String verdict;

    /** @param goals the program's initial goals ({@code !start}) */
    public FailureWatch(List<Literal> goals) {
        goals.forEach(g -> initialGoals.add(key(g)));
    }

    /** On the agent's thread: a plan was chosen for {@code event} at simulated time {@code nowMs}. */
    public void planSelected(Event event, long nowMs) {
        Trigger t = event.trigger();
        if (!(t.literal() instanceof Literal lit) || !t.isGoal()) {
            return;
        }
        if (!firstReasoningDone) {
            started.add(key(lit)); // a plan for it, or a failure plan for it, ran: the goal was handled
        }
        if (t.isAddition()) {
            return;
        }
        lastFailure = lit;
        if (verdict != null) {
            return;
        }
        long s = nowMs / 1000;
        if (s != second) {
            second = s;
            counts.clear();
        }
        String stormKey = key(lit) + " " + annot(lit, "error");
        int n = counts.merge(stormKey, 1, Integer::sum);
        if (n >= STORM_PER_SECOND) {
            verdict = String.format(Locale.ROOT, "failure storm at t=%.1f s: goal !%s failed %d times within one "
                    + "simulated second (%s); the run stops here", nowMs / 1000.0, goal(lit), n, why(lit));
        }
    }

    /**
     * After the agent's first reasoning (it has taken its initial goals): an initial goal no plan
     * took, relevant or applicable, left the agent with nothing to do.
     */
    public void firstReasoningDone(PlanLibrary plans, List<Literal> goals) {
        firstReasoningDone = true;
        if (verdict != null) {
            return;
        }
        for (Literal g : goals) {
            if (!started.contains(key(g))) {
                Trigger add = new Trigger(Trigger.Op.ADD, Trigger.Type.ACHIEVE, g);
                verdict = "no " + (plans.hasCandidate(add) ? "applicable" : "relevant") + " plan for the agent's initial goal !"
                        + g + ": it has nothing to do; the run stops here";
                return;
            }
        }
    }

    /**
     * On the agent's thread: goal {@code failure} failed at {@code nowMs} and no failure plan
     * handles it; its intention, started by goal {@code root}, is dropped.
     */
    public void failureUnhandled(Literal failure, Literal root, long nowMs) {
        lastFailure = failure;
        if (verdict != null) {
            return;
        }
        boolean initial = initialGoals.contains(key(root));
        Literal reason = failure.getAnnot("env_failure_reason");
        boolean unknownAction = reason != null && reason.arity() == 1 && reason.arg(0) instanceof Literal r
                && r.functor().equals("unknown_operation");
        if (initial || unknownAction) {
            verdict = String.format(Locale.ROOT, "goal !%s failed at t=%.1f s and no plan handles its failure (%s): %s; "
                    + "the run stops here", goal(failure), nowMs / 1000.0, why(failure),
                    unknownAction ? "the action does not exist" : "the agent dropped its initial goal !" + goal(root));
        }
    }

    /** The system stopped ({@code .stopMAS}) at {@code nowMs}, before the run's end. */
    public void systemStopped(long nowMs) {
        if (verdict == null) {
            verdict = String.format(Locale.ROOT, "the agent stopped the system (.stopMAS) at t=%.1f s, before the run's end",
                    nowMs / 1000.0) + (lastFailure == null ? "" : ", after goal !" + goal(lastFailure) + " failed (" + why(lastFailure) + ")");
        }
    }

    /**
     * The agent ran {@code cycles} reasoning cycles in control step {@code step} (at {@code nowMs})
     * without going idle, {@code running} the labels of its plans ready to run then: it loops within
     * the step, and simulated time would never move on.
     */
    public void reasoningRanAway(long cycles, long step, long nowMs, List<String> running) {
        if (verdict == null) {
            verdict = String.format(Locale.ROOT, "reasoning ran away in control step %d at t=%.2f s: %d reasoning cycles "
                    + "without going idle (a plan that loops without waiting, or an action failing again and again)%s; "
                    + "the run stops here", step, nowMs / 1000.0, cycles,
                    running.isEmpty() ? "" : ", running " + String.join(", ", running));
        }
    }

    /** {@return why the agent failed at its job, once it has} */
    public Optional<String> verdict() {
        return Optional.ofNullable(verdict);
    }

    /** {@code error ID, error_msg "..."} and where, from a failure event's annotations. */
    private static String why(Literal failure) {
        StringBuilder b = new StringBuilder("error ").append(annot(failure, "error"));
        String msg = annot(failure, "error_msg");
        if (!msg.isEmpty()) {
            b.append(", error_msg \"").append(msg).append('"');
        }
        String src = annot(failure, "code_src");
        String line = annot(failure, "code_line");
        if (!src.isEmpty() && !line.isEmpty()) {
            b.append(", at ").append(src.replaceFirst("^file:", "")).append(':').append(line);
        }
        return b.toString();
    }

    private static String annot(Literal l, String functor) {
        Literal a = l.getAnnot(functor);
        if (a == null || a.arity() == 0) {
            return "";
        }
        Term v = a.arg(0);
        if (v instanceof StringTerm s) {
            return s.value();
        }
        if (v instanceof NumberTerm n) {
            return String.valueOf((long) n.value());
        }
        return v.toString();
    }

    /** The goal without its annotations: {@code go(3)}. */
    private static String goal(Literal l) {
        return new Literal(l.functor(), l.args(), List.of(), l.negated(), l.operandAtom(), l.ns()).toString();
    }

    private static String key(Literal l) {
        return l.functor() + "/" + l.arity();
    }
}
