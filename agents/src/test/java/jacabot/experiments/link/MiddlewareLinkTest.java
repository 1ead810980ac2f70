package jacabot.experiments.link;

import static jacabot.experiments.link.LinkTestSupport.await;
import static jacabot.experiments.link.LinkTestSupport.waitFor;
import static jacabot.experiments.link.LinkTestSupport.wheels;
import static jacabot.experiments.link.LinkTestSupport.world;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.Command;
import jacabot.robot.link.Handshake;
import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import jacabot.robot.link.Uplink;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.SocketException;
import java.util.Date;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The middleware's end of the link, against the real controller and against hostile clients. */
class MiddlewareLinkTest {
    private final List<String> log = new CopyOnWriteArrayList<>();
    /** The key of the links these tests open themselves ({@link BothEnds} makes its own). */
    static final LinkSecret SECRET = LinkSecret.random();

    private LinkConfig linkConfig() {
        return LinkConfig.defaults().withPort(0).withLog(log::add).withSecret(SECRET);
    }

    @Test
    void afterAHandOverEveryEventGoesToTheHandlerInOrderTheQueuedOnesFirst() throws Exception {
        // real time: at 20x a loaded machine let the 4096-event queue overflow (oldest readings and
        // markers dropped, by design) before this thread handed over, and step 0 was gone
        var cc = ControllerConfig.defaults().withSpeedFactor(1).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, linkConfig())) {
            MiddlewareLink m = link.middleware();
            assertTrue(m.awaitConnected(LinkTestSupport.DEADLINE_S, TimeUnit.SECONDS));
            // the middleware's side of the handshake ends first; a real-time step the controller
            // takes before its own side has ended is dropped (no link yet), and would be step 0
            waitFor(() -> link.controller().isConnected());
            link.controller().runner().start();
            List<LinkEvent> handled = new CopyOnWriteArrayList<>();
            waitFor(() -> m.simTimeMs() >= 400); // ten steps queue up before the hand-over
            m.handOver(handled::add);
            waitFor(() -> handled.stream().filter(e -> e instanceof LinkEvent.StepMarker).count() >= 20);
            link.controller().runner().stop();
            assertInstanceOf(LinkEvent.Connected.class, handled.get(0), "the queued events came first");
            long lastStep = -1;
            for (LinkEvent e : handled) {
                if (e instanceof LinkEvent.StepMarker) {
                    assertEquals(lastStep + 1, ((LinkEvent.StepMarker) e).step(), "markers in order, none lost");
                    lastStep = ((LinkEvent.StepMarker) e).step();
                }
            }
            assertEquals(null, m.poll(50, TimeUnit.MILLISECONDS), "nothing left in the queue");
        }
    }

    @Test
    void aControllerConnectsSendsReadingsWithSimulatedTimeAndObeysCommands() throws Exception {
        var cc = ControllerConfig.defaults().withSpeedFactor(20).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, linkConfig())) {
            link.controller().runner().start();
            MiddlewareLink m = link.middleware();
            var connected = (LinkEvent.Connected) await(m, e -> e instanceof LinkEvent.Connected);
            assertEquals("khepera", connected.robotName());
            assertFalse(connected.lockstep());
            assertTrue(m.isConnected());
            var r = (LinkEvent.Reading) await(m, e -> e instanceof LinkEvent.Reading
                    && ((LinkEvent.Reading) e).info().getId() == SensorKind.CENTRAL_DISTANCE.id());
            assertEquals(40 * r.step(), r.simTimeMs());
            assertTrue(m.send(Command.setSpeeds(40, 40)));
            await(m, wheels(40, 40));
            await(m, e -> e instanceof LinkEvent.StepMarker && !((LinkEvent.StepMarker) e).awaitsAck());
            waitFor(() -> m.timings().response().count() > 0);
            assertEquals(1, m.timings().response().count(), "the APPLIED report gives one response time");
            assertTrue(m.timings().transport().count() > 0);
            link.controller().runner().stop();
        }
    }

    @Test
    void failSafeStopsTheRobotWhenTheAgentSideIsSilentAndReconnectionRestoresConnected() throws Exception {
        AtomicLong nanos = new AtomicLong();
        var cc = ControllerConfig.defaults().withSpeedFactor(20).withFailSafeMs(1000).withBackoff(20, 100)
                .withClocks(LinkClock.system(), nanos::get).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, linkConfig().withHeartbeatMs(0))) {
            link.controller().runner().start();
            MiddlewareLink m = link.middleware();
            await(m, e -> e instanceof LinkEvent.Connected);
            m.send(Command.forward());
            await(m, wheels(50, 50));
            nanos.addAndGet(TimeUnit.SECONDS.toNanos(2)); // the agent side says nothing for 2 s
            var f = (LinkEvent.FailSafe) await(m, e -> e instanceof LinkEvent.FailSafe);
            assertTrue(f.reason().startsWith("no command or heartbeat"), f.reason());
            await(m, wheels(0, 0));

            m.send(Command.forward());
            await(m, wheels(50, 50));
            m.disconnect("test: pulling the cable");
            var gone = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
            assertEquals("test: pulling the cable", gone.reason());
            await(m, e -> e instanceof LinkEvent.Connected); // the controller came back by itself
            assertTrue(m.isConnected());
            await(m, wheels(0, 0)); // and stopped meanwhile
            // the controller counts the connection once its end of the handshake is done, which a
            // loaded machine may run after the middleware's Connected event
            waitFor(() -> link.controller().connections() >= 2);
            assertEquals(2, link.controller().connections());
            link.controller().runner().stop();
        }
    }

    /**
     * A client that shakes hands properly (with the secret, for this version) and then writes
     * whatever the test wants.
     */
    static Socket handshake(MiddlewareLink m, int version) throws Exception {
        Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port());
        var hello = new Protocol.Hello(version, "rogue", "none", 40, false);
        var out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
        if (version == Protocol.VERSION) {
            Handshake.asController(new DataInputStream(s.getInputStream()), out, hello, SECRET);
        } else {
            hello.write(out);
        }
        return s;
    }

    private static void expectClosedWith(MiddlewareLink m, String reason) throws InterruptedException {
        var d = (LinkEvent.Disconnected) await(m, e -> e instanceof LinkEvent.Disconnected);
        assertTrue(d.reason().contains(reason), d.reason());
        assertFalse(m.isConnected());
    }

    /** A batch announcing one reading, with an object in its place. */
    private static void writeBatchWith(Socket s, Object payload) throws Exception {
        var out = new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream()));
        out.writeByte(Uplink.BATCH);
        out.writeLong(0);
        out.writeLong(0);
        out.writeLong(0);
        out.writeInt(1);
        out.writeObject(payload);
        out.flush();
    }

    @Test
    void aForeignClassOrAHugeArrayClosesTheConnectionWithALoggedReason() throws Exception {
        try (var m = MiddlewareLink.open(linkConfig())) {
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                writeBatchWith(s, new Date(0)); // an object where a reading's fields belong: never built
                expectClosedWith(m, "carried something other than its fields");
            }
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                try {
                    RawFrames.batch(new ObjectOutputStream(new BufferedOutputStream(s.getOutputStream())), 0,
                            new SensorInfo(SensorKind.CAMERA_IMAGE.id(), new int[10_000_000]));
                } catch (SocketException e) {
                    // the middleware hung up in the middle of the 40 MB: as it should
                }
                expectClosedWith(m, "array of 10000000 elements exceeds the limit");
            }
            assertTrue(log.stream().anyMatch(l -> l.startsWith("connection closed: rejected: array of 10000000 elements")),
                    log.toString());
        }
    }

    @Test
    void garbageStrangersAndOtherVersionsAreRefusedAndTheLinkKeepsServing() throws Exception {
        try (var m = MiddlewareLink.open(linkConfig())) {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                s.getOutputStream().write("GET / HTTP/1.1\r\n\r\n".getBytes());
                waitFor(() -> m.lastCloseReason() != null);
                assertTrue(m.lastCloseReason().startsWith("not a jacabot controller"), m.lastCloseReason());
            }
            try (Socket s = handshake(m, Protocol.VERSION + 7)) {
                var welcome = Protocol.Welcome.read(new DataInputStream(s.getInputStream()));
                assertFalse(welcome.accepted());
                assertTrue(welcome.message().startsWith("protocol version mismatch"), welcome.message());
            }
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                var out = new ObjectOutputStream(s.getOutputStream());
                out.writeByte(77); // an unknown frame tag
                out.flush();
                expectClosedWith(m, "unknown frame tag 77");
            }
            try (Socket s = handshake(m, Protocol.VERSION)) {
                await(m, e -> e instanceof LinkEvent.Connected);
                var out = new ObjectOutputStream(s.getOutputStream());
                out.writeByte(Uplink.BATCH);
                out.writeLong(3); // and then nothing: the frame is truncated
                out.flush();
                s.shutdownOutput();
                expectClosedWith(m, "truncated frame");
            }
            // still serving: a real controller gets through
            var cc = ControllerConfig.defaults().withAddress("127.0.0.1", m.port()).withLog(log::add).withSecret(SECRET);
            try (var controller = new RobotController(world("obstacle-avoidance"), cc)) {
                controller.start();
                var c = (LinkEvent.Connected) await(m, e -> e instanceof LinkEvent.Connected);
                assertEquals("mybot", c.robotName());
                assertNotNull(m.robot());
            }
        }
    }

    /**
     * Real time never runs ahead of the wall clock x the factor (a load on the machine can only slow it
     * down, so this bound does not flake; how close it keeps to the factor is a benchmark's figure).
     */
    @Test
    void realTimeModeNeverRunsAheadOfTheFactor() throws Exception {
        var cc = ControllerConfig.defaults().withSpeedFactor(4).withLog(log::add);
        try (var link = BothEnds.start(world("navigation"), cc, linkConfig())) {
            var runner = link.controller().runner();
            long wall0 = System.nanoTime(), sim0 = link.controller().world().timeMs();
            runner.start();
            waitFor(() -> link.controller().world().timeMs() - sim0 >= 2000);
            runner.stop();
            double wallS = (System.nanoTime() - wall0) / 1e9;
            double simS = (link.controller().world().timeMs() - sim0) / 1000.0;
            int step = link.controller().world().controlStep();
            assertTrue(simS <= 4 * wallS + step / 1000.0, simS + " s simulated in " + wallS + " s at factor 4");
        }
    }

    @Test
    void sendingWithoutAControllerReportsFalse() throws Exception {
        try (var m = MiddlewareLink.open(linkConfig())) {
            assertFalse(m.send(Command.stop()));
            assertFalse(m.awaitConnected(10, TimeUnit.MILLISECONDS));
            assertTrue(m.port() > 0, "a free port was chosen: " + m.port());
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), m.port())) {
                assertTrue(s.isConnected(), "it listens there");
            }
        }
    }
}
