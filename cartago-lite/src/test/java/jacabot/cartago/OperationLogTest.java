package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** A workspace's operation log (a debugger's artifacts panel): which operations ran, for whom, when, and how they ended. */
class OperationLogTest {
    /** A stock that fails when asked for more than it holds. */
    public static class Stock extends Artifact {
        void init(int items) {
            defineObsProperty("items", items);
        }

        @OPERATION
        void take(int n) {
            ObsProperty items = getObsProperty("items");
            if (n > items.intValue()) {
                failed("only " + items.intValue() + " left", "not_enough", items.intValue());
            }
            items.updateValue(items.intValue() - n);
        }

        @OPERATION
        void waitOneSecond() {
            await_time(1000);
        }
    }

    @Test
    void offByDefaultThenTheLastOperationsOfEachAgentWithTheirTimesAndOutcomes() throws CartagoException {
        SimulatedClock clock = new SimulatedClock();
        try (Workspace ws = Calls.quiet("main").stepped().clock(clock).build()) {
            AgentId alice = ws.join("alice", new RecordingObserver());
            AgentId bob = ws.join("bob", new RecordingObserver());
            ArtifactId stock = ws.createArtifact("stock", Stock.class, 10);
            ok(ws, alice, "take", 1);
            assertFalse(ws.recordsOperations());
            assertEquals(List.of(), ws.operationLog(stock), "nothing is recorded while the log is off");

            ws.recordOperations(2);
            assertTrue(ws.recordsOperations());
            clock.advance(1000);
            ok(ws, alice, "take", 1);
            ok(ws, bob, "take", 2);
            clock.advance(500);
            assertEquals("not_enough", Calls.failure(ws, alice, OpTarget.any(), "take", 50).reasonFunctor());
            ok(ws, alice, "take", 3);
            // alice's first operation since the log is on has gone (two kept per agent); bob's stays
            assertEquals(List.of(
                    new OperationRecord(1000, 1000, "bob", "take/1", true, ""),
                    new OperationRecord(1500, 1500, "alice", "take/1", false, "not_enough"),
                    new OperationRecord(1500, 1500, "alice", "take/1", true, "")), ws.operationLog(stock));
            assertEquals(List.of(), ws.operationLog(ws.lookup("console").orElseThrow()), "each artifact has its own log");
        }
    }

    @Test
    void anOperationThatWaitsIsRecordedFromItsStartToItsEnd() throws CartagoException {
        SimulatedClock clock = new SimulatedClock(2000);
        try (Workspace ws = Calls.quiet("main").stepped().clock(clock).build()) {
            AgentId alice = ws.join("alice", new RecordingObserver());
            ArtifactId stock = ws.createArtifact("stock", Stock.class, 1);
            ws.recordOperations(5);
            var done = Calls.start(ws, alice, OpTarget.any(), "waitOneSecond");
            ws.runPending();
            assertEquals(List.of(), ws.operationLog(stock), "recorded when it completes");
            clock.advance(1000);
            ws.runPending();
            assertTrue(done.isDone());
            assertEquals(List.of(new OperationRecord(2000, 3000, "alice", "waitOneSecond/0", true, "")), ws.operationLog(stock));
            ws.recordOperations(0);
            ok(ws, alice, "take", 1);
            assertEquals(1, ws.operationLog(stock).size(), "off again: nothing more is added");
            ws.disposeArtifact(stock);
            assertEquals(List.of(), ws.operationLog(stock));
            assertThrows(IllegalArgumentException.class, () -> ws.recordOperations(-1));
        }
    }
}
