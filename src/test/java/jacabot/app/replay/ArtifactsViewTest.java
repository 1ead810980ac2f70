package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.ArtifactInfo;
import jacabot.app.inspector.ArtifactInfo.LoggedOperation;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpTarget;
import jacabot.cartago.SimulatedClock;
import jacabot.cartago.Workspace;
import jacabot.cartago.examples.Counter;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

/** The artifacts panel's view of a live workspace: operations are recorded from its first reading on, not before. */
class ArtifactsViewTest {
    @Test
    void theOperationLogStartsWithThePanelsFirstReading() throws Exception {
        SimulatedClock clock = new SimulatedClock();
        try (Workspace ws = Workspace.builder("main").stepped().clock(clock).logger(CartagoLogger.silent()).build()) {
            AgentId alice = ws.join("alice", new ArtifactObserverAdapter());
            ws.createArtifact("c", Counter.class);
            Supplier<Map<String, ArtifactInfo>> view = ArtifactsView.of(ws);
            inc(ws, alice);
            assertFalse(ws.recordsOperations(), "nobody has looked: nothing is recorded");
            assertEquals(List.of(), view.get().get("c").log());
            assertTrue(ws.recordsOperations());
            clock.advance(1250);
            inc(ws, alice);
            ArtifactInfo c = view.get().get("c");
            assertEquals(List.of(new LoggedOperation(1250, 1250, "alice", "inc/0", "ok")), c.log());
            assertEquals(List.of("inc/0"), c.operations());
        }
    }

    private static void inc(Workspace ws, AgentId agent) {
        ws.execOp(agent, OpTarget.name("c"), "inc", new Object[0], outcome -> assertTrue(outcome.succeeded(), outcome::toString));
        ws.runPending();
    }
}
