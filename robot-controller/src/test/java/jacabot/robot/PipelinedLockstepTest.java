package jacabot.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The controller in a pipelined lockstep against a bare middleware: the world advances one control
 * step past a step it sent before it waits for that step's answer, and the answer to step k is
 * applied at step k+1 (one control step of latency, not more).
 */
class PipelinedLockstepTest {
    private FakeMiddleware middleware;
    private RobotController controller;

    @BeforeEach
    void start() throws Exception {
        middleware = new FakeMiddleware();
        controller = middleware.startController(ControllerConfig.defaults().withLockstep(true).withLog(l -> { }), true);
    }

    @AfterEach
    void stop() throws Exception {
        middleware.stop(controller);
    }

    @Test
    void theWorldSimulatesTheNextStepWhileTheAgentReasonsAndTheAnswerIsAppliedThere() throws Exception {
        try (var peer = middleware.accept(Protocol.VERSION)) {
            assertTrue(peer.awaitMarker(0).awaitsAck());
            long controlStep = controller.world().controlStep();
            long end = System.nanoTime() + 5_000_000_000L;
            while (controller.world().timeMs() < controlStep && System.nanoTime() < end) {
                Thread.sleep(5); // step 0 unanswered: the world simulates it anyway
            }
            Thread.sleep(100);
            assertEquals(controlStep, controller.world().timeMs(), "one step ahead of the agent, and no more");
            assertEquals(-1, controller.lastAnsweredStep());
            peer.send(Command.setSpeeds(30, 40));
            peer.send(Command.stepAck(0));
            var applied = (Uplink.Applied) peer.await(f -> f instanceof Uplink.Applied);
            assertEquals(1, applied.step(), "the answer to step 0 applied at step 1");
            assertEquals(controlStep, applied.simTimeMs());
            peer.awaitMarker(1); // sampled before the answer was applied: the wheels as they were
            peer.send(Command.stepAck(1));
            assertEquals(2, peer.awaitWheels(30, 40).step(), "in effect from step 1 to 2: at step 2's readings");
        }
    }

    @Test
    void realTimeHasNoPipeline() throws Exception {
        var realTime = new RobotController(RobotControllerTest.world("navigation"), ControllerConfig.defaults());
        assertThrows(IllegalArgumentException.class, () -> realTime.pipelined(true)); // never started: nothing to close
    }
}
