package jacabot.experiments.team;

import static jacabot.experiments.team.Ops.fails;
import static jacabot.experiments.team.Ops.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.CartagoException;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.Workspace;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The charger's queue: ordered by need (the least energy first, equal needs first come, first
 * served); the head holds the charger once its wait ends, until it leaves, and nobody is put
 * before it then.
 */
class ChargerQueueTest {
    /** {@return whether the call completes within 200 ms} (used only where it must not: a wait that does not end) */
    private static boolean completesSoon(CompletableFuture<OpOutcome> call) {
        try {
            call.get(200, TimeUnit.MILLISECONDS);
            return true;
        } catch (Exception e) {
            return false;
        }
    }

    @Test
    void theHeadHoldsTheChargerAndTheNextWaitsUntilItLeaves() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("charger", ChargerQueue.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher()), c = ws.join("c", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "w", "charger");

            ok(ws, a, "charger", "requestCharger");
            ok(ws, b, "charger", "requestCharger");
            ok(ws, a, "charger", "requestCharger"); // already queued: keeps its place
            ok(ws, a, "charger", "awaitCharger");   // the head: at once
            CompletableFuture<OpOutcome> bWaits = Ops.start(ws, b, "charger", "awaitCharger");
            assertFalse(completesSoon(bWaits), "b waits while a holds the charger");
            CompletableFuture<OpOutcome> cWaits = Ops.start(ws, c, "charger", "awaitCharger"); // c arrives after b
            assertFalse(completesSoon(cWaits));
            assertEquals(List.of(List.of(List.of(a, b, c))), sees.values("chargerQueue"));

            ok(ws, a, "charger", "leaveCharger");
            assertTrue(bWaits.join().succeeded(), "b's turn");
            assertFalse(cWaits.isDone(), "c still waits");
            ok(ws, c, "charger", "leaveCharger"); // c gives up its place: its wait ends, failed
            assertEquals("not_queued", ((OpOutcome.Failure) cWaits.join()).reasonFunctor());
            assertEquals(List.of(List.of(List.of(b))), sees.values("chargerQueue"));
            ok(ws, a, "charger", "leaveCharger"); // not queued: fine
        }
    }

    @Test
    void anAgentThatLeavesTheWorkspaceLeavesTheQueue() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("charger", ChargerQueue.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher());
            ok(ws, a, "charger", "awaitCharger");
            CompletableFuture<OpOutcome> bWaits = Ops.start(ws, b, "charger", "awaitCharger");
            assertFalse(completesSoon(bWaits));
            ws.leave(a); // a's process ended while it held the charger
            assertTrue(bWaits.join().succeeded(), "b holds the charger");
        }
    }

    @Test
    void aHolderThatCannotReachTheChargerLetsTheNextGoFirst() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("charger", ChargerQueue.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher()), c = ws.join("c", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "w", "charger");
            ok(ws, a, "charger", "awaitCharger");
            ok(ws, a, "charger", "yieldCharger"); // alone: keeps the charger
            assertEquals(List.of(List.of(List.of(a))), sees.values("chargerQueue"));
            ok(ws, b, "charger", "requestCharger");
            ok(ws, c, "charger", "requestCharger");
            CompletableFuture<OpOutcome> bWaits = Ops.start(ws, b, "charger", "awaitCharger");
            assertFalse(completesSoon(bWaits));
            ok(ws, b, "charger", "yieldCharger"); // not the holder: nothing changes
            ok(ws, a, "charger", "yieldCharger");
            assertTrue(bWaits.join().succeeded(), "b holds the charger");
            assertEquals(List.of(List.of(List.of(b, a, c))), sees.values("chargerQueue"), "a second, before c");
        }
    }

    /** The robot with the least energy goes first, whatever the order of the calls; the holder is never overtaken. */
    @Test
    void theQueueIsOrderedByNeedAndTheHolderKeepsTheCharger() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("charger", ChargerQueue.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher()), c = ws.join("c", new Ops.Watcher()),
                    d = ws.join("d", new Ops.Watcher()), e = ws.join("e", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "w", "charger");

            ok(ws, a, "charger", "requestCharger", 450.0);
            ok(ws, a, "charger", "awaitCharger");                 // a holds the charger
            ok(ws, b, "charger", "requestCharger", 400.0);
            ok(ws, c, "charger", "requestCharger", 300.0);
            ok(ws, d, "charger", "requestCharger", 400.0);        // as needy as b, later: behind b
            assertEquals(List.of(List.of(List.of(a, c, b, d))), sees.values("chargerQueue"));
            ok(ws, e, "charger", "requestCharger", 100.0);        // the neediest: before all but the holder
            assertEquals(List.of(List.of(List.of(a, e, c, b, d))), sees.values("chargerQueue"));
            ok(ws, d, "charger", "requestCharger", 250.0);        // d's need grew: it moves up
            assertEquals(List.of(List.of(List.of(a, e, d, c, b))), sees.values("chargerQueue"));

            ok(ws, a, "charger", "leaveCharger");                 // e's turn; still on its way
            ok(ws, c, "charger", "requestCharger", 50.0);         // c is needier now: it overtakes e
            assertEquals(List.of(List.of(List.of(c, e, d, b))), sees.values("chargerQueue"));
            ok(ws, c, "charger", "awaitCharger");                 // c holds it
            ok(ws, b, "charger", "requestCharger", 10.0);         // however needy, b waits for c
            assertEquals(List.of(List.of(List.of(c, b, e, d))), sees.values("chargerQueue"));
            fails("bad_energy", List.of(-1.0), ws, b, "charger", "requestCharger", -1.0);
        }
    }

    /**
     * A robot waiting at the charger goes before the robots that booked from afar, however needy:
     * it does not wait while they travel; those waiting in the order they arrived, a needier one
     * arriving later behind them (else a robot waiting there was overtaken again and again). The energies of the
     * robots waiting behind the holder are published for it.
     */
    @Test
    void robotsWaitingAtTheChargerGoBeforeTheBookedOnes() throws CartagoException {
        try (Workspace ws = Ops.workspace()) {
            ws.createArtifact("charger", ChargerQueue.class);
            AgentId a = ws.join("a", new Ops.Watcher()), b = ws.join("b", new Ops.Watcher()), c = ws.join("c", new Ops.Watcher()),
                    d = ws.join("d", new Ops.Watcher());
            Ops.Watcher sees = Ops.watch(ws, "w", "charger");

            ok(ws, a, "charger", "requestCharger", 450.0);
            ok(ws, a, "charger", "awaitCharger");                 // a holds the charger
            ok(ws, b, "charger", "requestCharger", 100.0);        // booked from afar, very needy
            ok(ws, c, "charger", "requestCharger", 400.0);
            assertEquals(List.of(List.of(List.of(a, b, c))), sees.values("chargerQueue"));
            assertEquals(List.of(List.of(List.of())), sees.values("chargerWaiting"), "nobody waits at the charger");
            CompletableFuture<OpOutcome> cWaits = Ops.start(ws, c, "charger", "awaitCharger"); // c arrives
            assertFalse(completesSoon(cWaits));
            assertEquals(List.of(List.of(List.of(a, c, b))), sees.values("chargerQueue"), "c waits there: before b");
            assertEquals(List.of(List.of(List.of(400.0))), sees.values("chargerWaiting"));
            ok(ws, d, "charger", "requestCharger", 300.0);        // d arrives later, needier than c
            CompletableFuture<OpOutcome> dWaits = Ops.start(ws, d, "charger", "awaitCharger");
            assertFalse(completesSoon(dWaits));
            assertEquals(List.of(List.of(List.of(a, c, d, b))), sees.values("chargerQueue"), "in the order of arrival");
            assertEquals(List.of(List.of(List.of(400.0, 300.0))), sees.values("chargerWaiting"));
            ok(ws, b, "charger", "requestCharger", 50.0);         // b still on its way: behind them
            assertEquals(List.of(List.of(List.of(a, c, d, b))), sees.values("chargerQueue"));

            ok(ws, a, "charger", "leaveCharger");
            assertTrue(cWaits.join().succeeded(), "c holds the charger");
            assertFalse(completesSoon(dWaits), "d waits for c");
            assertEquals(List.of(List.of(List.of(300.0))), sees.values("chargerWaiting"));
        }
    }
}
