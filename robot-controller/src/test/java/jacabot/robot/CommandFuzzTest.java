package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.CommandCode;
import jacabot.robot.link.CommandWriter;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A middleware that holds the secret but sends garbage: random and mutated command frames at a live
 * controller, for a bounded time. The controller skips what it cannot apply, drops a connection it
 * cannot resynchronise (stopping the wheels), never lets its simulation thread die, never drives the
 * wheels past the motors' limits, and obeys a sane middleware afterwards. 3 s in CI; a minute with
 * {@code -Djacabot.tests=long}.
 */
class CommandFuzzTest {
    private final List<String> log = new CopyOnWriteArrayList<>();

    @Test
    void fuzzForThreeSeconds() throws Exception {
        fuzz(3, 7);
    }

    @Tag("long")
    @Test
    void fuzzForAMinute() throws Exception {
        fuzz(60, 1716);
    }

    private static byte[] validFrames(Random r) throws IOException {
        var bytes = new ByteArrayOutputStream();
        var w = new CommandWriter(bytes);
        List<Command> all = List.of(Command.forward(), Command.setSpeeds(30, -20), Command.turnLeft(), Command.stop(),
                Command.armDown(), Command.closeGrip(0.8), Command.enableSensor(SensorKind.GPS, 40),
                Command.disableSensor(SensorKind.BATTERY), Command.heartbeat(), Command.turnAround());
        for (int i = 0; i < 8; i++) {
            w.write(i, 0, all.get(r.nextInt(all.size())));
        }
        return bytes.toByteArray();
    }

    private static byte[] mutate(byte[] b, Random r) {
        byte[] m = b.clone();
        switch (r.nextInt(3)) {
            case 0:
                for (int i = 0, n = 1 + r.nextInt(6); i < n; i++) {
                    m[r.nextInt(m.length)] ^= (byte) (1 << r.nextInt(8));
                }
                return m;
            case 1:
                return Arrays.copyOf(m, r.nextInt(m.length));
            default:
                byte[] g = new byte[r.nextInt(200)];
                r.nextBytes(g);
                return g;
        }
    }

    private void fuzz(int seconds, long seed) throws Exception {
        Random r = new Random(seed);
        try (var middleware = new FakeMiddleware()) {
            var controller = middleware.startController(ControllerConfig.defaults().withSpeedFactor(10).withFailSafeMs(300)
                    .withBackoff(10, 50).withLog(log::add));
            try {
                double maxSpeed = controller.robot().model().maxSpeed();
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
                int connections = 0;
                while (System.nanoTime() < end) {
                    try (var peer = middleware.accept(Protocol.VERSION)) {
                        connections++;
                        for (int i = 0, n = 1 + r.nextInt(5); i < n; i++) {
                            byte[] frames = validFrames(r);
                            peer.raw.write(r.nextInt(4) == 0 ? frames : mutate(frames, r));
                            peer.raw.flush();
                            // odd arguments that are well-formed: huge, negative, tiny
                            double big = r.nextBoolean() ? 1e300 : -1e300;
                            peer.commands.write(1000 + i, 0, Command.of(CommandCode.SET_SPEEDS, big, r.nextGaussian() * 1e6));
                            peer.commands.write(2000 + i, 0, Command.of(CommandCode.ENABLE_SENSOR, r.nextInt(200) - 50, -r.nextInt(1000)));
                        }
                        Uplink f;
                        // a controller that keeps streaming would keep this loop going: drain for 200 ms at most
                        long drainEnd = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(200);
                        while (System.nanoTime() < drainEnd && (f = peer.frames.poll(20, TimeUnit.MILLISECONDS)) != null) {
                            if (f instanceof Uplink.Batch b) {
                                for (SensorInfo info : b.readings()) {
                                    if (info.getId() == SensorKind.WHEEL_SPEEDS.id()) {
                                        for (double v : info.getDoubleValues()) {
                                            assertTrue(Math.abs(v) <= maxSpeed, "wheel speed " + v + " past the motors' " + maxSpeed);
                                        }
                                    }
                                }
                            }
                        }
                    } catch (IOException e) {
                        // the controller hung up on garbage mid-handshake: it comes back
                    }
                }
                // a sane middleware afterwards: the robot stopped when its link went, and obeys again
                long t0 = controller.world().timeMs();
                try (var peer = middleware.accept(Protocol.VERSION)) {
                    peer.awaitWheels(0, 0);
                    peer.send(Command.setSpeeds(20, 20));
                    peer.awaitWheels(20, 20);
                }
                assertTrue(controller.world().timeMs() > t0, "the simulation still steps");
                System.out.println("CommandFuzzTest: " + connections + " connections in " + seconds + " s, "
                        + controller.connections() + " seen by the controller, " + controller.failSafeTrips()
                        + " fail-safe trips, " + log.stream().filter(l -> l.contains("skipped")).count() + " frames skipped");
                assertEquals(0, log.stream().filter(l -> l.contains("Exception")).count(), log.toString());
            } finally {
                controller.close();
                controller.runner().stop();
            }
        }
    }
}
