package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Agents using CArtAgO's classic example artifacts through the JaCa bridge. */
class JacaBridgeTest {
    private static final String EX = "jacabot.cartago.examples.";

    @Test
    void counterPropertyBecomesABeliefAndTickASignal() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("c0", "%sCounter", [], C); focus(C); inc; inc.
                +count(V)[artifact_name("c0"), percept_type(obs_prop), source(percept)] <- .print("count ", V).
                +tick[artifact_name(Id, "c0"), percept_type(obs_ev)] <- .print("tick").
                """.formatted(EX)).run(10_000);
        assertEquals(List.of("[user] count 0", "[user] count 1", "[user] tick", "[user] count 2", "[user] tick"), h.lines());
        var user = h.mas.agent("user");
        assertTrue(user.solver().believes(user.parser().parseTerm("count(2)[source(percept)]"), user.newUnifier()));
        assertTrue(!user.solver().believes(user.parser().parseTerm("count(1)"), user.newUnifier()), "the old value is gone");
        assertTrue(!user.solver().believes(user.parser().parseTerm("tick"), user.newUnifier()), "signals are not stored");
    }

    @Test
    void stopFocusRemovesTheBeliefs() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("c0", "%sCounter", [], C); focus(C); inc; stopFocus(C); !check.
                +!check : count(_) <- .print(still).
                +!check <- .print(forgotten).
                """.formatted(EX)).run(10_000);
        assertEquals(List.of("[user] forgotten"), h.lines());
    }

    @Test
    void aFailingOperationFailsTheActionWithItsReason() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("b", "%sBoundedCounter", [2], _); inc; inc; inc; .print(never).
                -!go[error(E), error_msg(M), env_failure_reason(R)] <- .print(E, " ", R, " ", M).
                """.formatted(EX)).run(10_000);
        assertEquals(List.of("[user] action_failed max_reached(2) inc failed: the counter is at its maximum 2"), h.lines());
    }

    @Test
    void outputParametersBindVariables() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("calc", "%sCalculator", [], _);
                        sum(1, 2.5, S); divide(7, 2, Q, R); .print(S, " ", Q, " ", R);
                        divide(1, 0, _, _).
                -!go[env_failure_reason(Why)] <- .print(Why).
                """.formatted(EX)).run(10_000);
        assertEquals(List.of("[user] 3.5 3 1", "[user] division_by_zero(1)"), h.lines());
    }

    @Test
    void producerAndConsumerShareABoundedBufferWithGuards() throws Exception {
        var h = new JacaHarness().agent("producer", """
                !produce(1).
                +!produce(11) <- .print(produced).
                +!produce(N) <- if (N == 1) { makeArtifact("buf", "%sBoundedBuffer", [2], _) };
                                put(N); !produce(N + 1).
                """.formatted(EX)).agent("consumer", """
                !consume(0, 0).
                +!consume(10, Sum) <- .print("sum ", Sum).
                +!consume(K, Sum) <- ?buffer(B); get(X)[artifact_id(B)]; !consume(K + 1, Sum + X).
                +?buffer(B) <- lookupArtifact("buf", B).
                -?buffer(B) <- ?buffer(B).
                """).run(200_000);
        assertTrue(h.lines().contains("[consumer] sum 55"), h.lines().toString());
        assertTrue(h.lines().contains("[producer] produced"), h.lines().toString());
    }

    @Test
    void clockTicksInSimulatedTime() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- makeArtifact("clock", "%sClock", [100], C); focus(C); start.
                +tick(3) <- stop; .print("three ticks").
                +tick(N) <- .print("tick ", N).
                """.formatted(EX)).run(10_000);
        assertEquals(List.of(), h.lines(), "no tick before simulated time passes");
        for (int i = 0; i < 5; i++) {
            h.clock.advance(100);
            h.run(10_000);
        }
        assertEquals(List.of("[user] tick 1", "[user] tick 2", "[user] three ticks"), h.lines());
        var user = h.mas.agent("user");
        assertTrue(user.solver().believes(user.parser().parseTerm("ticks(3)"), user.newUnifier()));
    }

    @Test
    void badRequestsFailTheActionAndTheAgentKeepsRunning() throws Exception {
        var h = new JacaHarness().agent("user", """
                !go.
                +!go <- !try(makeArtifact("x", "no.such.Class", [], _));
                        !try(makeArtifact("b", "%sBoundedCounter", ["not a number"], _));
                        !try(makeArtifact("c", "%sCounter", [], _));
                        !try(makeArtifact("c", "%sCounter", [], _));
                        !try(inc(1, 2));
                        !try(fly);
                        .print(alive).
                +!try(A) <- A.
                -!try(A)[error(action_failed), env_failure_reason(R)] <- .print(R).
                """.formatted(EX, EX, EX)).run(10_000);
        assertEquals(List.of(
                "[user] unknown_class(\"no.such.Class\")",
                "[user] init_failed(\"jacabot.cartago.examples.BoundedCounter\",\"argument 1 expected int, got \"not a number\" (String)\")",
                "[user] duplicate_name(\"c\")",
                "[user] wrong_arity(\"inc\",2)",
                "[user] unknown_operation(\"fly\",0)",
                "[user] alive"), h.lines());
    }
}
