package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/** Calls operations as an agent would and waits for their outcome (runs pending steps when stepped). */
final class Calls {
    private Calls() {
    }

    /** {@return the outcome of {@code op(args...)} on {@code target}, waiting up to 10 s} */
    static OpOutcome call(Workspace ws, AgentId agent, OpTarget target, String op, Object... args) {
        CompletableFuture<OpOutcome> outcome = start(ws, agent, target, op, args);
        if (ws.mode() == Workspace.Mode.STEPPED) {
            ws.runPending();
            assertTrue(outcome.isDone(), op + " did not complete within runPending()");
        }
        try {
            return outcome.get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new AssertionError(op + " did not complete", e);
        }
    }

    /** Asks for an operation and {@return its future outcome}, without running anything. */
    static CompletableFuture<OpOutcome> start(Workspace ws, AgentId agent, OpTarget target, String op, Object... args) {
        CompletableFuture<OpOutcome> outcome = new CompletableFuture<>();
        ws.execOp(agent, target, op, args, outcome::complete);
        return outcome;
    }

    /** {@return the success of an operation that must succeed} */
    static OpOutcome.Success ok(Workspace ws, AgentId agent, String op, Object... args) {
        OpOutcome outcome = call(ws, agent, OpTarget.any(), op, args);
        assertTrue(outcome.succeeded(), () -> op + " failed: " + outcome);
        return (OpOutcome.Success) outcome;
    }

    /** {@return the failure of an operation that must fail} */
    static OpOutcome.Failure failure(Workspace ws, AgentId agent, OpTarget target, String op, Object... args) {
        OpOutcome outcome = call(ws, agent, target, op, args);
        assertFalse(outcome.succeeded(), () -> op + " should have failed");
        return (OpOutcome.Failure) outcome;
    }

    /** Asserts the reason functor of a failure. */
    static void assertReason(String functor, OpOutcome.Failure failure) {
        assertEquals(functor, failure.reasonFunctor(), () -> "failure: " + failure);
    }

    /** {@return the id an operation gave back in its last output} */
    static ArtifactId makeArtifact(Workspace ws, AgentId agent, String name, Class<?> type, Object... params) {
        OpOutcome.Success made = ok(ws, agent, "makeArtifact", name, type.getName(), params, new OpFeedbackParam<ArtifactId>());
        return (ArtifactId) made.outputs().get(3);
    }

    /** A console output captured in memory. */
    static final class Console {
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        final PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);

        String text() {
            return bytes.toString(StandardCharsets.UTF_8).replace(System.lineSeparator(), "\n");
        }
    }

    /** {@return a builder with a silent logger, for quiet tests} */
    static Workspace.Builder quiet(String name) {
        return Workspace.builder(name).logger(CartagoLogger.silent());
    }
}
