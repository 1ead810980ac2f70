package jacabot.agent.stdlib;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.testing.TestAgent;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code .verbose}, {@code .perceive} and {@code .signal}: what jason-oracle/31 cannot show (bare console lines, percepts). */
class MoreStdlibTest {
    @Test
    void verboseZeroPrintsBareTextAndOneRestoresTheName() {
        var a = new TestAgent("""
                !g.
                +!g <- .verbose(0); .print(quiet); .verbose(1); .print(loud).
                """);
        a.cycles(10);
        assertEquals(List.of("quiet", "[bob] loud"), a.console);
    }

    @Test
    void verboseOfANonNumberFailsWithWrongArguments() {
        var a = new TestAgent("""
                !g.
                +!g <- .verbose(a); .print(not_reached).
                -!g[error(E), error_msg(M)] <- .print(E, " ", M).
                """);
        a.cycles(10);
        assertEquals(List.of("wrong_arguments Wrong argument for internal action 'verbose': 'a' is not a number"), a.printed());
    }

    @Test
    void perceiveTurnsPerceptsIntoBeliefsAtOnce() throws Exception {
        var a = new TestAgent("");
        a.percepts = List.of(Literal.atom("seen"));
        assertFalse(a.believes("seen[source(percept)]"));
        assertEquals(true, new Perceive().execute(a.agent, new Unifier(), new Term[0]));
        assertTrue(a.believes("seen[source(percept)]"), "believed without a reasoning cycle");
        a.percepts = List.of();
        new Perceive().execute(a.agent, new Unifier(), new Term[0]);
        assertFalse(a.believes("seen[source(percept)]"), "a percept gone is a belief gone");
    }

    @Test
    void signalOfANonTriggerFailsWithWrongArguments() {
        // Jason posts an event without trigger and its reasoning cycle throws; ours fails the intention
        var a = new TestAgent("""
                !g.
                +!g <- .signal(foo); .print(not_reached).
                -!g[error(E), error_msg(M)] <- .print(E, " ", M).
                """);
        a.cycles(10);
        assertEquals(List.of("wrong_arguments Wrong argument for internal action 'signal': 'foo' is not a trigger such as {+e}"), a.printed());
    }
}
