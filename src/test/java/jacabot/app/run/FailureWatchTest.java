package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.PlanLibrary;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Trigger;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The initial goals' check reads the goals plans were chosen for up to the agent's first
 * reasoning; after it, choosing a plan records nothing (a plan is chosen every reasoning cycle).
 */
class FailureWatchTest {
    private static final Literal START = Literal.atom("start");

    private static Event achieve(Trigger.Op op, Literal goal) {
        return new Event(new Trigger(op, Trigger.Type.ACHIEVE, goal), null);
    }

    /** A watch of !start told of the plans chosen for {@code chosen}, then of the first reasoning's end. */
    private static FailureWatch afterFirstReasoning(Event... chosen) {
        var watch = new FailureWatch(List.of(START));
        for (Event e : chosen) {
            watch.planSelected(e, 0);
        }
        watch.firstReasoningDone(new PlanLibrary(), List.of(START));
        return watch;
    }

    @Test
    void anInitialGoalAPlanOrAFailurePlanWasChosenForIsStarted() {
        assertEquals(Optional.empty(), afterFirstReasoning(achieve(Trigger.Op.ADD, START)).verdict());
        assertEquals(Optional.empty(), afterFirstReasoning(achieve(Trigger.Op.DEL, START)).verdict());
    }

    @Test
    void anInitialGoalNoPlanWasChosenForBeforeTheFirstReasoningEndsTheRun() {
        var watch = afterFirstReasoning(achieve(Trigger.Op.ADD, Literal.of("move", new NumberTerm(1))));
        assertTrue(watch.verdict().orElseThrow().startsWith("no relevant plan for the agent's initial goal !start"),
                watch.verdict().toString());
        watch.planSelected(achieve(Trigger.Op.ADD, START), 40); // too late, and the verdict stays
        assertTrue(watch.verdict().isPresent());
    }

    @Test
    void failuresAreStillCountedAfterTheFirstReasoning() {
        var watch = afterFirstReasoning(achieve(Trigger.Op.ADD, START));
        Literal failed = Literal.of("go", new NumberTerm(3));
        for (int i = 0; i < FailureWatch.STORM_PER_SECOND; i++) {
            watch.planSelected(achieve(Trigger.Op.DEL, failed), 5_000);
        }
        assertTrue(watch.verdict().orElseThrow().startsWith("failure storm at t=5.0 s: goal !go(3) failed 1000 times"),
                watch.verdict().toString());
    }
}
