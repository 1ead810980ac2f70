package jacabot.experiments.link;

import static jacabot.experiments.link.LinkTestSupport.await;
import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static jacabot.experiments.link.LinkTestSupport.world;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.Command;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.ReadingCheck;
import jacabot.robot.link.SensorDataWriter;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Random and mutated bytes at a live middleware with a live controller behind it, for a bounded
 * time: strangers' garbage, mutated greetings, and (with the secret: a faulty controller) mutated
 * sensor streams. Afterwards the real controller is connected again, the robot stopped whenever its
 * link was taken, nothing malformed reached the agent side, and the agent side still perceives and
 * is obeyed. 3 s in CI; a minute with {@code -Djacabot.tests=long}.
 */
class LinkFuzzTest {
    private final List<String> log = new CopyOnWriteArrayList<>();
    private final List<String> controllerLog = new CopyOnWriteArrayList<>();

    @Test
    void fuzzForThreeSeconds() throws Exception {
        fuzz(3, 16);
    }

    @Tag("long")
    @Test
    void fuzzForAMinute() throws Exception {
        fuzz(60, 1716);
    }

    /** A valid sensor stream as the controller writes it: what the mutations start from. */
    private static byte[] validStream() throws IOException {
        var bytes = new ByteArrayOutputStream();
        var w = new SensorDataWriter(bytes, 3);
        for (int step = 0; step < 6; step++) {
            var readings = List.of(new SensorInfo(SensorKind.LEFT_DISTANCE.id(), 100 + step),
                    new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[] {1, 2, 3, 4, 5, 6, 7, 8, 9}),
                    new SensorInfo(SensorKind.GPS.id(), 0.1, 0, -0.2),
                    new SensorInfo(SensorKind.WHEEL_SPEEDS.id(), new double[] {step, -step}));
            w.writeStep(new Uplink.Batch(step, 40L * step, 0, readings), new Uplink.StepMarker(step, 40L * step, false));
            w.writeApplied(new Uplink.Applied(step, 3, step, 40L * step, 0, 0));
        }
        w.writeFailSafe(new Uplink.FailSafe(240, "fuzz"));
        return bytes.toByteArray();
    }

    private static byte[] mutate(byte[] valid, Random r) {
        byte[] b = valid.clone();
        switch (r.nextInt(4)) {
            case 0: // bit flips
                for (int i = 0, n = 1 + r.nextInt(8); i < n; i++) {
                    b[r.nextInt(b.length)] ^= (byte) (1 << r.nextInt(8));
                }
                return b;
            case 1: // random bytes over a stretch
                int at = r.nextInt(b.length), len = Math.min(b.length - at, 1 + r.nextInt(16));
                for (int i = 0; i < len; i++) {
                    b[at + i] = (byte) r.nextInt(256);
                }
                return b;
            case 2: // truncated
                return Arrays.copyOf(b, r.nextInt(b.length));
            default: // a stretch repeated
                int from = r.nextInt(b.length), n = Math.min(b.length - from, 1 + r.nextInt(64));
                byte[] out = Arrays.copyOf(b, b.length + n);
                System.arraycopy(b, from, out, from + n, b.length - from);
                return out;
        }
    }

    private void fuzz(int seconds, long seed) throws Exception {
        LinkSecret secret = LinkSecret.random();
        var check = new ReadingCheck(Arrays.stream(SensorKind.values()).map(SensorKind::id).toList());
        List<String> malformedDelivered = new CopyOnWriteArrayList<>();
        var config = LinkConfig.defaults().withPort(0).withLog(log::add).withSecret(secret)
                .withGuards(new LinkConfig.Guards(300, 300, 3, 1000, 8));
        try (MiddlewareLink m = MiddlewareLink.open(config)) {
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", m.port()).withSecret(secret).withSpeedFactor(5)
                    .withFailSafeMs(1000).withBackoff(20, 100).withLog(controllerLog::add);
            try (RobotController controller = new RobotController(world("navigation"), cc)) {
                controller.start();
                controller.runner().start();
                await(m, e -> e instanceof LinkEvent.Connected);
                m.handOver(e -> {
                    if (e instanceof LinkEvent.Reading) {
                        String p = check.problem(((LinkEvent.Reading) e).info());
                        if (p != null) {
                            malformedDelivered.add(p);
                        }
                    }
                });
                byte[] valid = validStream();
                Random r = new Random(seed);
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
                int attempts = 0, authenticated = 0;
                while (System.nanoTime() < end) {
                    attempts++;
                    try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                        s.setSoTimeout(1000);
                        var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                        int kind = r.nextInt(10);
                        var hello = new Protocol.Hello(Protocol.VERSION, "fuzz", "fuzz", 40, false);
                        if (kind < 3) { // a stranger's garbage
                            byte[] g = new byte[r.nextInt(300)];
                            r.nextBytes(g);
                            out.write(g);
                            out.flush();
                        } else if (kind < 6) { // a mutated greeting, no secret
                            byte[] h = hello.bytes();
                            byte[] withNonce = Arrays.copyOf(h, h.length + Handshake.NONCE_BYTES + Handshake.MAC_BYTES);
                            out.write(mutate(withNonce, r));
                            out.flush();
                        } else { // a faulty controller: holds the secret, sends a mutated stream
                            Handshake.asController(new DataInputStream(s.getInputStream()), out, hello, secret);
                            authenticated++;
                            out.write(mutate(valid, r));
                            out.flush();
                        }
                        s.shutdownOutput();
                        s.getInputStream().read(new byte[4096]); // until the middleware has its say or hangs up
                    } catch (IOException e) {
                        // refused, reset, timed out: all fine
                    }
                }
                // the real controller comes back by itself and is obeyed
                m.handOver(e -> {
                });
                waitFor(() -> m.isConnected() && "khepera".equals(m.robot().robotName()));
                List<LinkEvent> after = new CopyOnWriteArrayList<>();
                m.handOver(after::add);
                assertTrue(m.send(Command.forward()) || waitThenSend(m));
                waitFor(() -> after.stream().anyMatch(e -> e instanceof LinkEvent.Reading
                        && ((LinkEvent.Reading) e).info().getId() == SensorKind.WHEEL_SPEEDS.id()
                        && ((LinkEvent.Reading) e).info().getDoubleValues()[0] == 50));
                System.out.println("LinkFuzzTest: " + attempts + " connections in " + seconds + " s (" + authenticated
                        + " with the secret and a mutated stream), " + m.failedHandshakes() + " failed handshakes, "
                        + m.badFrames() + " bad frames dropped, " + controller.connections() + " controller connections, "
                        + controller.failSafeTrips() + " fail-safe trips");
                assertNull(malformedDelivered.isEmpty() ? null : malformedDelivered.get(0),
                        "nothing malformed reached the agent side");
                long drops = controllerLog.stream().filter(l -> l.startsWith("fail-safe: the link to the middleware dropped")).count();
                if (controller.connections() > 1) {
                    assertTrue(drops >= 1, "each time its link was taken the robot stopped: " + controllerLog);
                }
                assertTrue(log.stream().noneMatch(l -> l.contains("link failed:")), "no unexpected exception: " + log);
                assertEquals(0, controllerLog.stream().filter(l -> l.contains("Exception")).count(), controllerLog.toString());
                controller.runner().stop();
            }
        }
    }

    private static boolean waitThenSend(MiddlewareLink m) throws InterruptedException {
        waitFor(m::isConnected);
        return m.send(Command.forward());
    }
}
