package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** One step at a time per artifact; different artifacts in parallel. */
class ConcurrencyTest {
    /** Counts how many steps are inside it at once, and updates a plain field racily on purpose. */
    public static class Hammer extends Artifact {
        private final AtomicInteger inside = new AtomicInteger();
        private int maxInside;
        private int hits;

        @OPERATION
        void hit() {
            int now = inside.incrementAndGet();
            maxInside = Math.max(maxInside, now);
            int read = hits;
            for (int i = 0; i < 200; i++) {
                Thread.onSpinWait();
            }
            Thread.yield();
            hits = read + 1;
            inside.decrementAndGet();
        }

        @OPERATION
        void hitAcrossAwait() {
            hit();
            await_time(0);
            hit();
        }

        @OPERATION
        void stats(OpFeedbackParam<Integer> count, OpFeedbackParam<Integer> max) {
            count.set(hits);
            max.set(maxInside);
        }
    }

    /** Counts down a shared latch, then waits (bounded) for the other party inside the step. */
    public static class Meeting extends Artifact {
        private CountDownLatch latch;

        void init(Object latch) {
            this.latch = (CountDownLatch) latch;
        }

        @OPERATION
        void arrive(long timeoutMillis) throws InterruptedException {
            latch.countDown();
            if (!latch.await(timeoutMillis, TimeUnit.MILLISECONDS)) {
                failed("the other party never arrived", "timeout");
            }
        }
    }

    @Test
    void twoAgentsHammeringOneArtifactNeverInterleaveInsideAStep() throws Exception {
        int perAgent = 400;
        try (Workspace ws = Calls.quiet("main").maxOperationThreads(8).build()) {
            AgentId a = ws.join("a", new RecordingObserver());
            AgentId b = ws.join("b", new RecordingObserver());
            ArtifactId hammer = ws.createArtifact("hammer", Hammer.class);
            CountDownLatch done = new CountDownLatch(2 * perAgent);
            AtomicInteger failures = new AtomicInteger();
            OpCallback count = outcome -> {
                if (!outcome.succeeded()) {
                    failures.incrementAndGet();
                }
                done.countDown();
            };
            Thread[] agents = new Thread[2];
            AgentId[] ids = {a, b};
            for (int t = 0; t < 2; t++) {
                AgentId agent = ids[t];
                agents[t] = new Thread(() -> {
                    for (int i = 0; i < perAgent; i++) {
                        ws.execOp(agent, OpTarget.id(hammer), i % 2 == 0 ? "hit" : "hitAcrossAwait", null, count);
                    }
                });
                agents[t].start();
            }
            for (Thread t : agents) {
                t.join();
            }
            assertTrue(done.await(60, TimeUnit.SECONDS), "all operations completed");
            assertEquals(0, failures.get());
            OpOutcome.Success stats = Calls.ok(ws, a, "stats", new OpFeedbackParam<>(), new OpFeedbackParam<>());
            assertEquals(3 * perAgent, stats.outputs().get(0), "no lost update: steps never overlapped");
            assertEquals(1, stats.outputs().get(1), "never more than one step inside");
        }
    }

    @Test
    void differentArtifactsRunInParallel() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            CountDownLatch latch = new CountDownLatch(2);
            ArtifactId m1 = ws.createArtifact("m1", Meeting.class, latch);
            ArtifactId m2 = ws.createArtifact("m2", Meeting.class, latch);
            CompletableFuture<OpOutcome> first = Calls.start(ws, agent, OpTarget.id(m1), "arrive", 30_000);
            CompletableFuture<OpOutcome> second = Calls.start(ws, agent, OpTarget.id(m2), "arrive", 30_000);
            assertTrue(first.get(60, TimeUnit.SECONDS).succeeded(), "m1's step saw m2's arrive while running");
            assertTrue(second.get(60, TimeUnit.SECONDS).succeeded());
        }
    }

    @Test
    void stepsOfOneArtifactDoNotRunInParallel() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            ArtifactId m = ws.createArtifact("m", Meeting.class, new CountDownLatch(2));
            CompletableFuture<OpOutcome> first = Calls.start(ws, agent, OpTarget.id(m), "arrive", 300);
            CompletableFuture<OpOutcome> second = Calls.start(ws, agent, OpTarget.id(m), "arrive", 300);
            // Whichever enters first waits alone and times out; only then can the other enter, and
            // it finds the latch open.
            List<OpOutcome> outcomes = List.of(first.get(60, TimeUnit.SECONDS), second.get(60, TimeUnit.SECONDS));
            assertEquals(1, outcomes.stream().filter(OpOutcome::succeeded).count(), outcomes.toString());
        }
    }

    @Test
    void steppedModeRunsNothingOutsideRunPending() throws Exception {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            ws.createArtifact("hammer", Hammer.class);
            CompletableFuture<OpOutcome> hit = Calls.start(ws, agent, OpTarget.any(), "hitAcrossAwait");
            assertFalse(hit.isDone());
            assertTrue(ws.runPending() >= 2, "the start and the continuation after await_time(0)");
            assertTrue(hit.isDone());
            OpOutcome.Success stats = Calls.ok(ws, agent, "stats", new OpFeedbackParam<>(), new OpFeedbackParam<>());
            assertEquals(2, stats.outputs().get(0));
        }
    }
}
