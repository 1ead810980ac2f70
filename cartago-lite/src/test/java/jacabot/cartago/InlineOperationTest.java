package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/** Workspace.execOpInline: a lockstep host's operation run on its own thread when it is next anyway. */
class InlineOperationTest {
    /** Counts, remembers the thread of its last step, and can wait. */
    public static final class Probe extends Artifact {
        volatile String lastThread;

        void init() {
            defineObsProperty("n", 0);
        }

        @OPERATION
        void inc() {
            lastThread = Thread.currentThread().getName();
            ObsProperty n = getObsProperty("n");
            n.updateValue(n.intValue() + 1);
        }

        @OPERATION
        void pause() {
            await_time(10);
        }
    }

    private static CompletableFuture<OpOutcome> inline(Workspace ws, AgentId host, String op) {
        CompletableFuture<OpOutcome> outcome = new CompletableFuture<>();
        ws.execOpInline(host, OpTarget.name("probe"), op, new Object[0], outcome::complete);
        return outcome;
    }

    private static Probe probe(Workspace ws) {
        return ws.artifactObject(ws.lookup("probe").orElseThrow(), Probe.class).orElseThrow();
    }

    @Test
    void anOperationThatIsNextRunsOnTheCallersThreadAndReportsAtTheNextRunPending() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId host = ws.join("host", obs);
            ws.createArtifact("probe", Probe.class);
            ok(ws, host, "focus", "probe");
            obs.expect("probe focused [n(0)]");
            CompletableFuture<OpOutcome> done = inline(ws, host, "inc");
            assertEquals(Thread.currentThread().getName(), probe(ws).lastThread, "ran on the caller's thread");
            assertFalse(done.isDone(), "the outcome waits for runPending, as for any stepped operation");
            assertEquals(0, ws.runPending(), "nothing left to run");
            assertTrue(done.join().succeeded());
            obs.expect("probe n(0)->n(1)");
        }
    }

    @Test
    void anOperationBehindAnotherIsQueuedInOrder() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId host = ws.join("host", new RecordingObserver());
            ws.createArtifact("probe", Probe.class);
            CompletableFuture<OpOutcome> first = Calls.start(ws, host, OpTarget.name("probe"), "inc");
            CompletableFuture<OpOutcome> second = inline(ws, host, "inc");
            assertEquals(null, probe(ws).lastThread, "neither ran yet: the first one is still queued");
            assertEquals(2, ws.runPending());
            assertTrue(first.join().succeeded() && second.join().succeeded());
            // it never waits (AwaitAnalysis), so runPending ran it on this thread rather than a carrier's
            assertEquals(Thread.currentThread().getName(), probe(ws).lastThread);
        }
    }

    /** Remembers the thread of each step of an operation that waits. */
    public static final class Sleeper extends Artifact {
        final List<String> threads = new CopyOnWriteArrayList<>();

        @OPERATION
        void nap() {
            threads.add(Thread.currentThread().getName());
            await_time(0);
            threads.add(Thread.currentThread().getName());
        }
    }

    @Test
    void atRunPendingAnOperationThatMayWaitRunsOnACarrierAndOneThatNeverWaitsHere() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId host = ws.join("host", new RecordingObserver());
            ws.createArtifact("probe", Probe.class);
            ws.createArtifact("sleeper", Sleeper.class);
            CompletableFuture<OpOutcome> nap = Calls.start(ws, host, OpTarget.name("sleeper"), "nap");
            CompletableFuture<OpOutcome> inc = Calls.start(ws, host, OpTarget.name("probe"), "inc");
            ws.runPending();
            assertTrue(nap.join().succeeded() && inc.join().succeeded());
            assertEquals(Thread.currentThread().getName(), probe(ws).lastThread);
            var sleeper = ws.artifactObject(ws.lookup("sleeper").orElseThrow(), Sleeper.class).orElseThrow();
            assertEquals(2, sleeper.threads.size());
            assertTrue(sleeper.threads.stream().allMatch(t -> t.startsWith("cartago-main-op-")), sleeper.threads.toString());
        }
    }

    @Test
    void anInlineOperationMayNotWait() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId host = ws.join("host", new RecordingObserver());
            ws.createArtifact("probe", Probe.class);
            CompletableFuture<OpOutcome> paused = inline(ws, host, "pause");
            ws.runPending();
            OpOutcome outcome = paused.join();
            assertFalse(outcome.succeeded());
            assertTrue(((OpOutcome.Failure) outcome).message().contains("await is not allowed in probe.pause(), which runs inline"),
                    outcome.toString());
            assertTrue(ok(ws, host, "inc").outputs().isEmpty(), "the artifact is free again");
        }
    }
}
