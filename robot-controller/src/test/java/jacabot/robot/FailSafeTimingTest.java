package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Reliability (docs/reliability.md): the robot stops within 200 ms of simulated time when the agent side falls silent, the
 * link is cut, or one bad frame comes, on the real clocks and the default fail-safe. Each case
 * prints its figure (docs/reliability.md). Simulated time is what the bound is about, so the
 * machine's load cannot break it: a world faster than the wall clock is held while it waits.
 */
class FailSafeTimingTest {
    private static final long BOUND_MS = 200;
    private static final Pattern TRIP = Pattern.compile("step (\\d+) fail-safe (.*)");

    private final List<String> events = new CopyOnWriteArrayList<>();

    private ControllerConfig config(double speed) {
        return ControllerConfig.defaults().withSpeedFactor(speed).withBackoff(20, 100)
                .withLog(line -> { }).withEventLog(events::add);
    }

    /** A silent cut: the socket stays open, nothing comes (a peer whose agent froze, a link that stopped forwarding). */
    @ParameterizedTest(name = "real time x{0}")
    @ValueSource(doubles = {1, 5})
    void aSilentAgentSideStopsTheRobotWithin200MsOfSimulatedTime(double speed) throws Exception {
        try (var middleware = new FakeMiddleware()) {
            var controller = middleware.startController(config(speed));
            try (var peer = middleware.accept(Protocol.VERSION)) {
                peer.send(Command.forward());
                var applied = (Uplink.Applied) peer.await(f -> f instanceof Uplink.Applied);
                var tripped = (Uplink.FailSafe) peer.await(f -> f instanceof Uplink.FailSafe);
                long drove = tripped.simTimeMs() - applied.simTimeMs();
                System.out.printf("fail-safe x%s: silence from t=%d ms, wheels stopped at t=%d ms: %d ms of simulated time (%s)%n",
                        speed, applied.simTimeMs(), tripped.simTimeMs(), drove, tripped.reason());
                assertTrue(drove >= ControllerConfig.FAIL_SAFE_MS && drove < BOUND_MS, drove + " ms");
                peer.awaitWheels(0, 0);
            } finally {
                middleware.stop(controller);
            }
        }
    }

    @Test
    void aCutLinkStopsTheRobotWithin200MsOfSimulatedTime() throws Exception {
        long drove = afterAFault("link cut", peer -> peer.close());
        assertTrue(drove < BOUND_MS, drove + " ms");
    }

    @Test
    void oneBadFrameStopsTheRobotWithin200MsOfSimulatedTime() throws Exception {
        long drove = afterAFault("one bad command frame", peer -> {
            peer.raw.write(new byte[] {0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 127, 127, 127, 127}); // argc 2^31-ish
            peer.raw.flush();
        });
        assertTrue(drove < BOUND_MS, drove + " ms");
    }

    interface Fault {
        void inflict(FakeMiddleware.Peer peer) throws IOException;
    }

    /**
     * Drives forward with heartbeats every 20 ms (so the silence fail-safe stays quiet), inflicts the
     * fault, and {@return the simulated ms from the fault to the step whose control stopped the wheels}.
     */
    private long afterAFault(String what, Fault fault) throws Exception {
        try (var middleware = new FakeMiddleware()) {
            var controller = middleware.startController(config(1));
            var peer = middleware.accept(Protocol.VERSION);
            try {
                peer.send(Command.forward());
                peer.awaitWheels(50, 50);
                Thread beats = new Thread(() -> {
                    try {
                        while (!Thread.currentThread().isInterrupted()) {
                            peer.send(Command.heartbeat());
                            Thread.sleep(20);
                        }
                    } catch (IOException | InterruptedException e) {
                        // cut
                    }
                });
                beats.start();
                Thread.sleep(300); // driving, heard from
                long faultAt;
                synchronized (controller.world()) {
                    faultAt = controller.world().timeMs();
                    beats.interrupt();
                    beats.join();
                    fault.inflict(peer);
                }
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                Matcher trip = null;
                while (trip == null && System.nanoTime() < end) {
                    for (String e : events) {
                        Matcher m = TRIP.matcher(e);
                        if (m.matches()) {
                            trip = m;
                        }
                    }
                    Thread.sleep(5);
                }
                assertTrue(trip != null, "no fail-safe after the " + what);
                long stoppedAt = Long.parseLong(trip.group(1)) * controller.world().controlStep();
                synchronized (controller.world()) {
                    assertEquals(0, controller.robot().getWheels().getLeftSpeed());
                }
                long drove = stoppedAt - faultAt;
                System.out.printf("fail-safe, %s at t=%d ms: wheels stopped at t=%d ms, %d ms of simulated time (%s)%n",
                        what, faultAt, stoppedAt, drove, trip.group(2));
                return drove;
            } finally {
                peer.close();
                middleware.stop(controller);
            }
        }
    }
}
