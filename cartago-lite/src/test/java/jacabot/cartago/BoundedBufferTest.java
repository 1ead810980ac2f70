package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.BoundedBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Guards: a producer and a consumer agent share a bounded buffer. */
class BoundedBufferTest {
    private static final int ITEMS = 300;

    @Test
    void aProducerAndAConsumerThreadExchangeEveryItemInOrder() throws Exception {
        try (Workspace ws = Calls.quiet("main").maxOperationThreads(4).build()) {
            AtomicInteger maxItems = new AtomicInteger();
            ArtifactObserver watcher = new ArtifactObserverAdapter() {
                @Override
                public void propertyUpdated(ArtifactId artifact, PropertySnapshot oldValue, PropertySnapshot newValue) {
                    maxItems.accumulateAndGet((Integer) newValue.value(), Math::max);
                }
            };
            AgentId producer = ws.join("producer", watcher);
            AgentId consumer = ws.join("consumer", new RecordingObserver());
            ArtifactId buffer = Calls.makeArtifact(ws, producer, "buffer", BoundedBuffer.class, 3);
            ok(ws, producer, "focus", buffer);

            ExecutorService agents = Executors.newFixedThreadPool(2);
            try {
                Future<?> produced = agents.submit(() -> {
                    for (int i = 0; i < ITEMS; i++) {
                        ok(ws, producer, "put", i);
                    }
                });
                Future<List<Object>> consumed = agents.submit(() -> {
                    List<Object> items = new ArrayList<>();
                    for (int i = 0; i < ITEMS; i++) {
                        items.add(ok(ws, consumer, "get", new OpFeedbackParam<>()).outputs().get(0));
                    }
                    return items;
                });
                produced.get(60, TimeUnit.SECONDS);
                List<Object> expected = new ArrayList<>();
                for (int i = 0; i < ITEMS; i++) {
                    expected.add(i);
                }
                assertEquals(expected, consumed.get(60, TimeUnit.SECONDS));
            } finally {
                agents.shutdownNow();
            }
            assertTrue(maxItems.get() <= 3, "the buffer never held more than its capacity: " + maxItems);
        }
    }

    @Test
    void steppedGetWaitsForItsGuardUntilAPutCommits() {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ArtifactId buffer = Calls.makeArtifact(ws, agent, "buffer", BoundedBuffer.class, 1);
            ok(ws, agent, "focus", buffer);
            obs.expect("buffer focused [n_items(0)]");

            CompletableFuture<OpOutcome> get = Calls.start(ws, agent, OpTarget.any(), "get", new OpFeedbackParam<>());
            CompletableFuture<OpOutcome> filled = Calls.start(ws, agent, OpTarget.any(), "waitFor", 2);
            ws.runPending();
            assertFalse(get.isDone());
            assertFalse(filled.isDone());

            ok(ws, agent, "put", "a");
            assertEquals("a", ((OpOutcome.Success) get.join()).outputs().get(0));
            obs.expect("buffer n_items(0)->n_items(1)", "buffer n_items(1)->n_items(0)");

            CompletableFuture<OpOutcome> put1 = Calls.start(ws, agent, OpTarget.any(), "put", "b");
            CompletableFuture<OpOutcome> put2 = Calls.start(ws, agent, OpTarget.any(), "put", "c");
            ws.runPending();
            assertTrue(put1.join().succeeded());
            assertFalse(put2.isDone(), "capacity 1: the second put waits");
            assertFalse(filled.isDone());
            assertEquals("b", ok(ws, agent, "get", new OpFeedbackParam<>()).outputs().get(0));
            assertTrue(put2.isDone());
        }
    }

    @Test
    void awaitOnAGuardReleasesTheArtifactUntilTheGuardHolds() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ArtifactId buffer = Calls.makeArtifact(ws, agent, "buffer", BoundedBuffer.class, 5);
            ok(ws, agent, "focus", buffer);
            CompletableFuture<OpOutcome> filled = Calls.start(ws, agent, OpTarget.any(), "waitFor", 2);
            ok(ws, agent, "put", 1);
            ok(ws, agent, "put", 2);
            assertTrue(Calls.call(ws, agent, OpTarget.any(), "waitFor", 0).succeeded());
            assertTrue(filled.get(10, TimeUnit.SECONDS).succeeded());
            assertTrue(obs.seen().contains("buffer !filled[2]"), obs.seen().toString());
        }
    }

    @Test
    void operationsWaitingOnADisposedArtifactFail() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            ArtifactId buffer = Calls.makeArtifact(ws, agent, "buffer", BoundedBuffer.class, 1);
            CompletableFuture<OpOutcome> get = Calls.start(ws, agent, OpTarget.id(buffer), "get", new OpFeedbackParam<>());
            ok(ws, agent, "disposeArtifact", buffer);
            OpOutcome outcome = get.get(10, TimeUnit.SECONDS);
            assertEquals("artifact_disposed", ((OpOutcome.Failure) outcome).reasonFunctor());
        }
    }
}
