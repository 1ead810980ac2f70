package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.LockstepTurn;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.SocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A lockstep controller whose middleware is in its process ({@link RobotController#takeTurnsWith}):
 * after writing each step, its simulation thread hands the middleware its turn, naming the
 * connection, and reads the answer only then; closing releases the turns.
 */
class MiddlewareTurnTest {
    /** A middleware taking its turns on the controller's thread: it answers each step with its acknowledgement. */
    private static final class Turns implements LockstepTurn {
        final List<String> taken = new CopyOnWriteArrayList<>();
        final List<Uplink.Applied> applied = new CopyOnWriteArrayList<>();
        final CountDownLatch released = new CountDownLatch(1);
        volatile FakeMiddleware.Peer peer;

        @Override
        public boolean take(SocketAddress controller, long step) {
            try {
                // the step is written already: its marker is (or will be) on the peer's side
                peer.await(f -> {
                    if (f instanceof Uplink.Applied a) {
                        applied.add(a); // the last step's reports come with this step's data
                    }
                    return f instanceof Uplink.StepMarker && ((Uplink.StepMarker) f).step() == step;
                });
                boolean sameConnection = controller.equals(peer.socket.getRemoteSocketAddress());
                taken.add(Thread.currentThread().getName() + " step " + step + (sameConnection ? " on its connection" : " elsewhere"));
                if (step == 0) {
                    peer.send(Command.setSpeeds(30, 40));
                }
                peer.send(Command.stepAck(step));
                return true;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } catch (InterruptedException e) {
                throw new AssertionError(e);
            }
        }

        @Override
        public void release() {
            released.countDown();
        }
    }

    @Test
    void theSimulationThreadTakesTheMiddlewaresTurnBetweenWritingAStepAndReadingItsAnswer() throws Exception {
        var turns = new Turns();
        try (var middleware = new FakeMiddleware()) {
            var controller = new RobotController(RobotControllerTest.world("navigation"), ControllerConfig.defaults()
                    .withLockstep(true).withLog(line -> { }).withAddress("127.0.0.1", middleware.port()).withSecret(middleware.secret))
                    .takeTurnsWith(turns);
            controller.start();
            try (var peer = middleware.accept(Protocol.VERSION)) {
                turns.peer = peer;
                controller.runner().runFor(0.12); // three steps, on this thread
                String here = Thread.currentThread().getName();
                assertEquals(List.of(here + " step 0 on its connection", here + " step 1 on its connection",
                        here + " step 2 on its connection"), turns.taken);
                assertEquals(3, controller.steps(), "each answer read after its turn");
                assertEquals(1, turns.applied.size());
                assertEquals(0, turns.applied.get(0).step(), "the turn's command applied at the step it answered");
                assertEquals(1, turns.released.getCount(), "not released while the controller runs");
                controller.close();
                assertTrue(turns.released.await(10, TimeUnit.SECONDS), "closing the controller releases the turns");
            }
        }
    }
}
