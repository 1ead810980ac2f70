package jacabot.cartago;

import static jacabot.cartago.Calls.failure;
import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.Calculator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Output parameters and CArtAgO's argument conversion. */
class CalculatorTest {
    private Workspace ws;
    private AgentId agent;

    private void setUp(Workspace workspace) throws CartagoException {
        ws = workspace;
        agent = ws.join("alice", new RecordingObserver());
        ws.createArtifact("calc", Calculator.class);
    }

    @Test
    void outputParametersAreReportedByIndexAndSetOnTheCallersMarkers() throws CartagoException {
        try (Workspace workspace = Calls.quiet("main").build()) {
            setUp(workspace);
            OpFeedbackParam<Object> sum = new OpFeedbackParam<>();
            assertEquals(Map.of(2, 5.5), ok(ws, agent, "sum", 2, 3.5, sum).outputs());
            assertEquals(5.5, sum.get());

            OpFeedbackParam<Object> q = new OpFeedbackParam<>();
            OpFeedbackParam<Object> r = new OpFeedbackParam<>();
            assertEquals(Map.of(2, 3, 3, 2), ok(ws, agent, "divide", 17.0, 5.0, q, r).outputs());
            assertEquals(3, q.get());
            assertEquals(2, r.get());
        }
    }

    @Test
    void aFailingOperationBindsNothing() throws CartagoException {
        try (Workspace workspace = Calls.quiet("main").stepped().build()) {
            setUp(workspace);
            OpFeedbackParam<Object> q = new OpFeedbackParam<>();
            OpOutcome.Failure f = failure(ws, agent, OpTarget.name("calc"), "divide", 1, 0, q, new OpFeedbackParam<>());
            assertEquals(new OpOutcome.Failure("division by zero", "division_by_zero", List.of(1)), f);
            assertFalse(q.isSet());
        }
    }

    @Test
    void numbersConvertToTheParameterTypeAndNeverBecomeBytes() throws CartagoException {
        try (Workspace workspace = Calls.quiet("main").stepped().build()) {
            setUp(workspace);
            assertEquals(5, echo(5.0));
            assertEquals(Integer.class, echo((byte) 5).getClass());
            assertEquals(5.5, echo(5.5f));
            assertEquals(10_000_000_000L, echo(1e10));
            assertEquals(List.of(1, 2.5, "a"), echo(List.of(1.0, 2.5, "a")));
            assertEquals("text", echo("text"));

            OpOutcome.Failure f = failure(ws, agent, OpTarget.any(), "divide", 5.5, 1, new OpFeedbackParam<>(), new OpFeedbackParam<>());
            Calls.assertReason("bad_argument", f);
            assertEquals(List.of(1), f.reasonArgs());
            assertTrue(f.message().contains("argument 1"), f.message());

            f = failure(ws, agent, OpTarget.any(), "sum", 1, 2, 3);
            Calls.assertReason("bad_argument", f);
            assertTrue(f.message().contains("unbound variable"), f.message());

            f = failure(ws, agent, OpTarget.any(), "sum", new OpFeedbackParam<>(), 2, new OpFeedbackParam<>());
            Calls.assertReason("bad_argument", f);
        }
    }

    private Object echo(Object value) {
        return ok(ws, agent, "echo", value, new OpFeedbackParam<>()).outputs().get(1);
    }
}
