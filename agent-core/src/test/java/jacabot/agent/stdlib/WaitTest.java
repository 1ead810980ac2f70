package jacabot.agent.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code .wait} in simulated time: nothing depends on the wall clock. */
class WaitTest {
    @Test
    void waitForATimeUsesTheAgentsClock() {
        var a = new TestAgent("""
                !g.
                +!g <- .print(before); .wait(5000); .print(after).
                """);
        a.cycles(10);
        assertEquals(List.of("before"), a.printed());
        a.advance(4999, 10);
        assertEquals(List.of("before"), a.printed(), "not a millisecond early");
        a.advance(1, 10);
        assertEquals(List.of("before", "after"), a.printed());
    }

    @Test
    void timeoutFailsWithWaitTimeoutAndElapsedTimeIsReported() {
        var a = new TestAgent("""
                !g. !h.
                +!g <- .wait({+never}, 300).
                -!g[error(E)] <- .print(E).
                +!h <- .wait({+ping}, 1000, T); .print(elapsed, T).
                """);
        a.cycles(10);
        a.advance(300, 10);
        assertEquals(List.of("wait_timeout"), a.printed());
        a.advance(700, 10);
        assertEquals(List.of("wait_timeout", "elapsed1000"), a.printed());
    }

    /** An atomic plan's wait that times out goes to its failure plan, as any other (it waited again and again). */
    @Test
    void anAtomicWaitThatTimesOutFailsOnce() {
        var a = new TestAgent("""
                !g.
                @g[atomic] +!g <- .wait({+never}, 300); .print(never).
                -!g[error(E)] <- .print(E).
                """);
        a.cycles(10);
        a.advance(300, 10);
        assertEquals(List.of("wait_timeout"), a.printed());
        a.advance(1000, 10);
        assertEquals(List.of("wait_timeout"), a.printed());
    }

    @Test
    void waitForAnEventBindsItsVariables() {
        var a = new TestAgent("""
                !w.
                +!w <- .wait({+level(L)}); .print(L).
                +!go <- +level(7).
                """);
        a.cycles(10);
        assertTrue(a.agent.canSleep());
        a.agent.addExternalEvent(new Trigger(Trigger.Op.ADD,
                Trigger.Type.ACHIEVE, Literal.atom("go")));
        a.cycles(20);
        assertEquals(List.of("7"), a.printed());
    }
}
