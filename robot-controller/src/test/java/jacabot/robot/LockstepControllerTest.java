package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import java.io.DataOutputStream;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The controller in lockstep against a bare middleware: the world waits for each step's
 * {@code STEP_ACK} (releasing the world's lock meanwhile); a dropped link stops the wheels, and
 * after reconnecting the controller sends the unanswered step again.
 */
class LockstepControllerTest {
    private final List<String> log = new CopyOnWriteArrayList<>();
    private FakeMiddleware middleware;
    private RobotController controller;

    @BeforeEach
    void start() throws Exception {
        middleware = new FakeMiddleware();
        controller = middleware.startController(ControllerConfig.defaults().withLockstep(true).withBackoff(20, 100)
                .withLog(log::add));
    }

    @AfterEach
    void stop() throws Exception {
        middleware.stop(controller);
    }

    @Test
    void theWorldAdvancesOnlyWhenTheStepIsAcknowledgedAndItsCommandsAreAppliedFirst() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            assertTrue(peer.hello.lockstep());
            assertTrue(peer.awaitMarker(0).awaitsAck());
            Thread.sleep(100); // unanswered, the world stays at step 0
            assertEquals(0, controller.steps());
            assertEquals(0, controller.world().timeMs());
            peer.send(Command.setSpeeds(30, 40));
            peer.send(Command.stepAck(0));
            var applied = (Uplink.Applied) peer.await(f -> f instanceof Uplink.Applied); // comes with step 1's data
            assertEquals(0, applied.step(), "applied at the step it answered");
            assertEquals(1, peer.awaitWheels(30, 40).step(), "in effect at the next step's readings");
            peer.awaitMarker(1);
        }
    }

    @Test
    void whileTheAgentReasonsTheWorldsLockIsFreeForAViewer() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            peer.awaitMarker(0);
            var locked = new CountDownLatch(1);
            Thread viewer = new Thread(() -> {
                synchronized (controller.world()) {
                    locked.countDown();
                }
            });
            viewer.start();
            assertTrue(locked.await(5, TimeUnit.SECONDS), "a viewer takes the world's lock during the agent's turn");
            peer.send(Command.stepAck(0));
            peer.awaitMarker(1);
        }
    }

    @Test
    void anUnknownCodeIsSkippedAndTheStepGoesOn() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            peer.awaitMarker(0);
            var out = new DataOutputStream(peer.raw);
            out.writeInt(999); // unknown code, well-formed frame
            out.writeInt(1);
            out.writeLong(0);
            out.writeInt(0);
            out.flush();
            peer.send(Command.stepAck(0));
            peer.awaitMarker(1);
            assertTrue(log.stream().anyMatch(l -> l.contains("unknown command code 999")), log.toString());
        }
    }

    @Test
    void aDroppedLinkStopsTheWheelsAndTheUnansweredStepIsSentAgainAfterReconnecting() throws Exception {
        var peer = middleware.accept(Protocol.VERSION);
        peer.awaitMarker(0);
        peer.send(Command.forward());
        peer.send(Command.stepAck(0));
        peer.awaitMarker(1);
        peer.close(); // step 1 is never answered
        try (var again = middleware.accept(Protocol.VERSION)) {
            var resent = again.awaitMarker(1);
            assertTrue(resent.awaitsAck());
            assertEquals(1, controller.steps(), "the world waited at step 1");
            assertEquals(1, controller.failSafeTrips());
            assertTrue(log.stream().anyMatch(l -> l.startsWith("fail-safe: the link to the middleware dropped; wheels stopped")),
                    log.toString());
            again.send(Command.stepAck(1));
            again.awaitMarker(2);
            assertEquals(2, controller.connections());
        }
    }
}
