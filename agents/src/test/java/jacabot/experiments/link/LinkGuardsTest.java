package jacabot.experiments.link;

import static jacabot.experiments.link.LinkTestSupport.await;
import static jacabot.experiments.link.MiddlewareLinkTest.handshake;
import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static jacabot.experiments.link.LinkTestSupport.world;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.AuthenticationException;
import jacabot.robot.link.Command;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorInfoFilter;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketException;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;

/**
 * The middleware's guards against a hostile or faulty peer (docs/reliability.md): who may drive,
 * what a frame may hold, how long it may take, how much a connection may cost, and what the agent
 * is told.
 */
class LinkGuardsTest {
    private final List<String> log = new CopyOnWriteArrayList<>();

    private LinkConfig config() {
        return LinkConfig.defaults().withPort(0).withLog(log::add).withSecret(MiddlewareLinkTest.SECRET);
    }

    private static ObjectOutputStream frames(Socket s) throws IOException {
        return new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream()));
    }


    private static boolean reading(LinkEvent e, SensorKind kind) {
        return e instanceof LinkEvent.Reading && ((LinkEvent.Reading) e).info().getId() == kind.id();
    }

    @Test
    void aMalformedReadingIsDroppedTheConnectionLivesAndTooManyCloseIt() throws Exception {
        try (var m = MiddlewareLink.open(config().withGuards(new LinkConfig.Guards(2000, 2000, 3, 20, 8)));
             Socket s = handshake(m, Protocol.VERSION)) {
            await(m, e -> e instanceof LinkEvent.Connected);
            var out = frames(s);
            // the audit's reading: filter-legal, an empty gripper array (it killed the serving loop)
            RawFrames.batch(out, 0, new SensorInfo(SensorKind.GRIPPER_POSITIONS.id(), new double[0]));
            RawFrames.batch(out, 1, new SensorInfo(SensorKind.CENTRAL_DISTANCE.id(), 120.0));
            var good = (LinkEvent.Reading) await(m, e -> reading(e, SensorKind.CENTRAL_DISTANCE));
            assertEquals(1, good.step(), "the bad batch went, the next one came through");
            assertEquals(1, m.badFrames());
            assertTrue(log.stream().anyMatch(l -> l.contains("GRIPPER_POSITIONS: 0 values, expected 2")), log.toString());
            RawFrames.batch(out, 2, new SensorInfo(SensorKind.LEFT_DISTANCE.id(), Double.NaN));
            RawFrames.batch(out, 3, new SensorInfo(SensorKind.CAMERA_SECTIONS.id(), new int[] {1, 2}));
            RawFrames.batch(out, 4, new SensorInfo(SensorKind.GPS.id(), 5.0)); // a scalar where a triple belongs
            var gone = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
            assertTrue(gone.reason().startsWith("more than 3 bad frames"), gone.reason());
        }
    }

    @Test
    void aReadingOfADeviceTheRobotDidNotDeclareIsRefused() throws Exception {
        try (var m = MiddlewareLink.open(config());
             Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
            var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
            var hello = new Protocol.Hello(Protocol.VERSION, "mybot", "w", 40, false, List.of(SensorKind.LEFT_DISTANCE.id()));
            Handshake.asController(new DataInputStream(s.getInputStream()), out, hello, MiddlewareLinkTest.SECRET);
            await(m, e -> e instanceof LinkEvent.Connected);
            var frames = frames(s);
            RawFrames.batch(frames, 0, new SensorInfo(SensorKind.BATTERY.id(), 10.0));
            RawFrames.batch(frames, 1, new SensorInfo(SensorKind.LEFT_DISTANCE.id(), 10.0));
            assertEquals(1, ((LinkEvent.Reading) await(m, e -> e instanceof LinkEvent.Reading)).step());
            assertTrue(log.stream().anyMatch(l -> l.contains("sensor id 30 was not declared")), log.toString());
        }
    }

    @Test
    void withoutTheSecretNobodyTakesTheSessionOver() throws Exception {
        var cc = ControllerConfig.defaults().withSpeedFactor(10).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, config().withHeartbeatMs(50))) {
            MiddlewareLink m = link.middleware();
            await(m, e -> e instanceof LinkEvent.Connected);
            link.controller().runner().start();
            LinkSecret wrong = LinkSecret.random();
            int authFailures = 0;
            for (int i = 0; i < 100; i++) {
                try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                    s.setSoTimeout(5000);
                    Handshake.asController(new DataInputStream(s.getInputStream()),
                            new DataOutputStream(new BufferedOutputStream(s.getOutputStream())),
                            new Protocol.Hello(Protocol.VERSION, "khepera", "navigation", 40, false), wrong);
                    throw new AssertionError("an intruder shook hands");
                } catch (AuthenticationException e) {
                    authFailures++; // the middleware could not be told from a stranger: good, it was not fooled
                } catch (IOException e) {
                    // refused unheard (rate limit) or closed: also a failure to take over
                }
            }
            assertTrue(authFailures > 0, "some attempts got as far as the proof");
            waitFor(() -> m.failedHandshakes() >= 100); // every attempt counted (the last ones as their threads end)
            assertEquals(1, link.controller().connections(), "the controller was never cut off");
            assertTrue(m.isConnected());
            for (LinkEvent e = m.poll(0, TimeUnit.MILLISECONDS); e != null; e = m.poll(0, TimeUnit.MILLISECONDS)) {
                assertFalse(e instanceof LinkEvent.Disconnected || e instanceof LinkEvent.Connected, e.toString());
            }
            await(m, e -> reading(e, SensorKind.CENTRAL_DISTANCE)); // still perceiving
            assertTrue(log.stream().anyMatch(l -> l.startsWith("refused a connection: ")), log.toString());
            assertTrue(log.size() < 60, "failed attempts are logged at a bounded rate: " + log.size() + " lines");
            link.controller().runner().stop();
        }
    }

    @Test
    void aControllerWithAnotherSecretIsRefusedAndSaysWhy() throws Exception {
        try (var m = MiddlewareLink.open(config())) {
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", m.port()).withSecret(LinkSecret.random())
                    .withBackoff(50, 100).withLog(log::add);
            try (var c = new RobotController(world("navigation"), cc)) {
                c.start();
                waitFor(() -> c.lastProblem() != null);
                assertTrue(c.lastProblem().startsWith("the middleware cannot prove the link secret"), c.lastProblem());
                assertFalse(m.isConnected());
            }
        }
    }

    @Test
    void aSlowHandshakeOrASlowFrameIsCutOff() throws Exception {
        try (var m = MiddlewareLink.open(config().withGuards(new LinkConfig.Guards(300, 300, 10, 20, 8)))) {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                OutputStream out = s.getOutputStream();
                byte[] hello = new Protocol.Hello(Protocol.VERSION, "slow", "w", 40, false).bytes();
                s.setSoTimeout(5000);
                assertThrows(IOException.class, () -> {
                    for (byte b : hello) { // a byte every 100 ms: each read is quick, the whole is not
                        out.write(b);
                        out.flush();
                        Thread.sleep(100);
                        if (s.getInputStream().available() < 0) {
                            break;
                        }
                    }
                    s.getInputStream().read(); // the middleware hung up
                    throw new IOException("closed");
                });
                waitFor(() -> m.lastCloseReason() != null);
                assertTrue(m.lastCloseReason().startsWith("no complete handshake within 300 ms"), m.lastCloseReason());
            }
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                var out = frames(s);
                out.writeByte(Uplink.BATCH);
                out.writeLong(0);
                out.flush(); // and the rest never comes
                var gone = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
                assertTrue(gone.reason().startsWith("a frame took longer than 300 ms"), gone.reason());
            }
        }
    }

    @Test
    void aStreamThatNeverRestartsOrAnOversizedBatchIsRefused() throws Exception {
        var limits = new SensorInfoFilter.Limits(1000, 3, 1000, 20_000, 30_000, 50);
        try (var m = MiddlewareLink.open(config().withLimits(limits))) {
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                var out = frames(s);
                for (int i = 0; i < 60; i++) { // 60 objects, never a restart
                    RawFrames.batch(out, i, new SensorInfo(SensorKind.LEFT_DISTANCE.id(), i));
                }
                var gone = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
                assertTrue(gone.reason().contains("more than 50 readings without a stream restart"), gone.reason());
            }
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                var out = frames(s);
                SensorInfo big = new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[902]); // 30x30 image, 3.6 kB
                SensorInfo[] many = new SensorInfo[10];
                Arrays.fill(many, 0, 10, null);
                for (int i = 0; i < 10; i++) {
                    many[i] = new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[902 + i]); // distinct objects
                }
                try {
                    RawFrames.batch(out, 0, big);
                    RawFrames.batch(out, 1, many); // each reading is allowed, the batch is not
                } catch (SocketException e) {
                    // the middleware hung up first
                }
                var gone = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
                assertTrue(gone.reason().contains("batch larger than 30000 bytes"), gone.reason());
            }
        }
    }

    @Test
    void aRestartedControllerDoesNotTurnTheClockBack() throws Exception {
        var secret = MiddlewareLinkTest.SECRET;
        try (var m = MiddlewareLink.open(config())) {
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", m.port()).withSecret(secret)
                    .withLockstep(true).withLog(log::add);
            long before;
            try (var first = new RobotController(world("navigation"), cc)) {
                m.handOver(e -> {
                    if (e instanceof LinkEvent.StepMarker) {
                        m.acknowledge(((LinkEvent.StepMarker) e).step());
                    }
                });
                first.start();
                first.runner().runFor(1.0);
                before = m.simTimeMs();
            }
            assertTrue(before >= 960, "the first controller ran a second: " + before);
            List<Long> times = new CopyOnWriteArrayList<>();
            m.handOver(e -> {
                if (e instanceof LinkEvent.StepMarker) {
                    times.add(((LinkEvent.StepMarker) e).simTimeMs());
                    m.acknowledge(((LinkEvent.StepMarker) e).step());
                }
            });
            try (var second = new RobotController(world("navigation"), cc)) { // starts at t = 0 again
                second.start();
                second.runner().runFor(0.2);
            }
            assertFalse(times.isEmpty());
            assertEquals(before + 40, times.get(0), "continues one control step after the last time seen");
            for (int i = 1; i < times.size(); i++) {
                assertEquals(times.get(i - 1) + 40, times.get(i));
            }
            assertTrue(log.stream().anyMatch(l -> l.contains("simulated clock went back")), log.toString());
        }
    }

    @Test
    void anAgentThatStopsReasoningLetsTheFailSafeStopTheRobotAndIsToldSo() throws Exception {
        AtomicBoolean reasoning = new AtomicBoolean(true);
        var cc = ControllerConfig.defaults().withSpeedFactor(5).withFailSafeMs(200).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, config().withHeartbeatMs(40))) {
            MiddlewareLink m = link.middleware();
            m.setLiveness(reasoning::get);
            link.controller().runner().start();
            await(m, e -> e instanceof LinkEvent.Connected);
            m.send(Command.forward());
            await(m, LinkTestSupport.wheels(50, 50));
            Thread.sleep(300);
            assertTrue(log.stream().noneMatch(l -> l.startsWith("the agent does not reason")), "heartbeats flow meanwhile");
            reasoning.set(false); // a cycle that never ends, a dead agent thread
            waitFor(() -> link.controller().failSafeTrips() > 0);
            var f = (LinkEvent.FailSafe) await(m, e -> e instanceof LinkEvent.FailSafe);
            assertTrue(f.reason().startsWith("no command or heartbeat"), f.reason());
            await(m, LinkTestSupport.wheels(0, 0));
            waitFor(() -> log.stream().anyMatch(l -> l.startsWith("the agent does not reason")));
            link.controller().runner().stop();
        }
    }

    @Test
    void aRefusedAttemptNeverCostsTheLiveSessionItsEvents() throws Exception {
        try (var m = MiddlewareLink.open(config())) {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                s.getOutputStream().write(new byte[] {0x4A, 0x43, 0x42, 0x54, 0, 0, 0, 2}); // magic, version, then silence
                s.getOutputStream().flush();
                s.shutdownOutput();
                waitFor(() -> m.lastCloseReason() != null);
            }
            assertNull(m.poll(50, TimeUnit.MILLISECONDS), "no Connected/Disconnected for a refused stranger");
        }
    }
}
