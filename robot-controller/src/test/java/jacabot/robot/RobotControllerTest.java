package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.CommandCode;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import jacabot.sim.SimWorld;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The controller against a bare middleware, in real-time mode at ×20 so that steps come quickly.
 * The fail-safe's silence is measured on a fake clock the test advances: no timed assertions.
 */
class RobotControllerTest {
    private final AtomicLong nanos = new AtomicLong();
    private final List<String> log = new CopyOnWriteArrayList<>();
    private FakeMiddleware middleware;
    private RobotController controller;

    static SimWorld world(String name) throws Exception {
        return SimWorld.load(Path.of(System.getProperty("jacabot.rootDir", "."), "worlds", name + ".json"));
    }

    @BeforeEach
    void start() throws Exception {
        middleware = new FakeMiddleware();
        controller = middleware.startController(ControllerConfig.defaults().withSpeedFactor(20).withFailSafeMs(500)
                .withBackoff(20, 100).withClocks(() -> 0, nanos::get).withLog(log::add));
    }

    @AfterEach
    void stop() throws Exception {
        middleware.stop(controller);
    }

    @Test
    void readingsCarryTheSimulatedTimeAndCommandsReachTheWheels() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            assertEquals("khepera", peer.hello.robotName());
            assertEquals(40, peer.hello.controlStepMs());
            var batch = (Uplink.Batch) peer.await(f -> f instanceof Uplink.Batch && ((Uplink.Batch) f).step() >= 2);
            assertEquals(40L * batch.step(), batch.simTimeMs(), "one control step of 40 ms per batch");
            assertTrue(batch.readings().stream().anyMatch(i -> i.getId() == SensorKind.CENTRAL_DISTANCE.id()));
            assertTrue(batch.readings().stream().anyMatch(i -> i.getId() == SensorKind.GPS.id()));
            peer.send(Command.setSpeeds(30, 40));
            var applied = (Uplink.Applied) peer.await(f -> f instanceof Uplink.Applied); // reported before the next batch
            assertEquals(CommandCode.SET_SPEEDS.code(), applied.code());
            peer.awaitWheels(30, 40);
        }
    }

    @Test
    void inRealTimeACommandReachesTheWheelsWhenItArrivesNotAtTheNextControlStep() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            peer.await(f -> f instanceof Uplink.Batch);
            controller.runner().stop(); // no control step from now on
            long steps = controller.steps();
            peer.send(Command.setSpeeds(30, 40));
            var applied = (Uplink.Applied) peer.await(f -> f instanceof Uplink.Applied);
            assertEquals(CommandCode.SET_SPEEDS.code(), applied.code());
            assertEquals(steps, controller.steps(), "applied while the world stood still");
            synchronized (controller.world()) {
                assertEquals(30, controller.robot().getWheels().getLeftSpeed());
                assertEquals(40, controller.robot().getWheels().getRightSpeed());
            }
        }
    }

    @Test
    void failSafeStopsTheWheelsWhenTheAgentSideGoesSilent() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            peer.send(Command.forward());
            peer.awaitWheels(50, 50);
            nanos.addAndGet(TimeUnit.MILLISECONDS.toNanos(600)); // 600 ms of silence
            var f = (Uplink.FailSafe) peer.await(x -> x instanceof Uplink.FailSafe);
            assertTrue(f.reason().startsWith("no command or heartbeat for 600 ms"), f.reason());
            peer.awaitWheels(0, 0);
            assertEquals(1, controller.failSafeTrips());
            peer.send(Command.heartbeat()); // alive again, but the robot waits for a new command
            peer.send(Command.turnLeft());
            peer.awaitWheels(20, 50);
        }
    }

    @Test
    void failSafeStopsTheWheelsWhenTheSocketClosesAndTheControllerReconnects() throws Exception {
        var peer = middleware.accept(Protocol.VERSION);
        peer.send(Command.forward());
        peer.awaitWheels(50, 50);
        peer.close();
        try (var again = middleware.accept(Protocol.VERSION)) {
            again.awaitWheels(0, 0);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (!controller.isConnected() && System.nanoTime() < end) {
                Thread.sleep(5); // the first batch may leave a moment before the inbox hears of the connection
            }
            assertTrue(controller.isConnected());
            assertEquals(2, controller.connections());
            assertTrue(log.stream().anyMatch(l -> l.startsWith("fail-safe: the link to the middleware dropped; wheels stopped")), log.toString());
        }
    }

    @Test
    void unknownCodesAndGarbageDoNotCrashTheController() throws Exception {
        var peer = middleware.accept(Protocol.VERSION);
        var out = new DataOutputStream(peer.raw);
        out.writeInt(999); // unknown code, well-formed frame: skipped, stream stays in step
        out.writeInt(1);
        out.writeLong(0);
        out.writeInt(1);
        out.writeDouble(3);
        out.flush();
        peer.send(Command.setSpeeds(10, 10));
        peer.awaitWheels(10, 10);
        assertTrue(log.stream().anyMatch(l -> l.contains("unknown command code 999")), log.toString());
        out.write(new byte[] {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 127, 127, 127, 127}); // garbage
        out.flush();
        try (var again = middleware.accept(Protocol.VERSION)) { // the controller dropped the garbage link and came back
            again.awaitWheels(0, 0);
            assertTrue(log.stream().anyMatch(l -> l.startsWith("garbage on the command stream")), log.toString());
        }
        peer.close();
    }

    @Test
    void aVersionMismatchIsRefusedWithAClearReason() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION + 1)) {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (controller.lastProblem() == null && System.nanoTime() < end) {
                Thread.sleep(10);
            }
            assertEquals("the middleware refused the connection: protocol version mismatch: the controller speaks version "
                    + Protocol.VERSION + ", the middleware version " + (Protocol.VERSION + 1), controller.lastProblem());
        }
    }

    @Test
    void aMiddlewareThatCannotProveTheSecretIsRefused() throws Exception {
        // a stranger listening on the port: its proof is made with another key
        // the controller hangs up before sending its own proof
        assertThrows(IOException.class,
                () -> middleware.accept(Protocol.VERSION, LinkSecret.random()));
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (controller.lastProblem() == null && System.nanoTime() < end) {
            Thread.sleep(10);
        }
        assertTrue(controller.lastProblem().startsWith("the middleware cannot prove the link secret"),
                controller.lastProblem());
        assertFalse(controller.isConnected());
        try (var peer = middleware.accept(Protocol.VERSION)) { // the real one is taken
            peer.awaitWheels(0, 0);
            long counted = System.nanoTime() + TimeUnit.SECONDS.toNanos(10); // the controller counts it on its own thread
            while (controller.connections() < 1 && System.nanoTime() < counted) {
                Thread.sleep(10);
            }
            assertEquals(1, controller.connections(), "the refused stranger is not counted");
        }
    }
}
