package jacabot.app.run;
import jacabot.experiments.link.LinkTestSupport;
import jacabot.experiments.link.StepData;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.link.Command;
import jacabot.robot.link.SensorKind;
import jacabot.sim.SimWorld;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Lockstep over the real protocol, with a scripted (non-AgentSpeak) agent side. */
class LockstepCoordinatorTest {
    /** Drives forward at full speed and stops for good once the front sensor reads over 350. */
    static final class StopAtObstacle implements LockstepCoordinator.AgentSide {
        long stoppedAt = -1;
        final List<double[]> wheels = new ArrayList<>();

        @Override
        public List<Command> step(StepData data) {
            wheels.add(data.reading(SensorKind.WHEEL_SPEEDS).orElseThrow().getDoubleValues());
            if (data.step() == 0) {
                return List.of(Command.setSpeeds(100, 100));
            }
            if (stoppedAt < 0 && data.value(SensorKind.CENTRAL_DISTANCE) > 350) {
                stoppedAt = data.step();
                return List.of(Command.stop());
            }
            return List.of();
        }
    }

    private static LockstepCoordinator.Result run(StopAtObstacle agent) throws Exception {
        SimWorld world = LinkTestSupport.world("navigation");
        return new LockstepCoordinator(world, "khepera", agent).runFor(10);
    }

    @Test
    void twoRunsOfTheSameWorldAndAgentGiveTheSameEventLogToTheByte() throws Exception {
        var first = run(new StopAtObstacle());
        var second = run(new StopAtObstacle());
        assertEquals(250, first.steps(), "10 s of 40 ms steps");
        assertTrue(first.controllerLog().size() >= 2 * 250, "readings and pose of every step");
        assertEquals(first.eventLog(), second.eventLog());
    }

    @Test
    void withTheMiddlewaresTurnsOnTheSimulationThreadTheRunIsTheSameToTheByte() throws Exception {
        var agent = new StopAtObstacle();
        var threads = run(new StopAtObstacle());
        var turns = new LockstepCoordinator(LinkTestSupport.world("navigation"), "khepera", agent).takeTurns(true).runFor(10);
        assertEquals(threads.eventLog(), turns.eventLog());
        assertTrue(agent.stoppedAt > 0, "the robot met red1 with the turns too");
    }

    @Test
    void aRunOverTheSocketGivesEachThreadsCpuAndTheSystemTimeWithinIt() throws Exception {
        var coordinator = new LockstepCoordinator(LinkTestSupport.world("navigation"), "khepera", new StopAtObstacle());
        coordinator.runFor(10);
        long[] t = coordinator.threadCpuNanos();
        assertEquals(4, t.length);
        for (int thread = 0; thread < 2; thread++) {
            assertTrue(t[thread] > 0, "thread " + thread + " worked: " + t[thread]);
            assertTrue(t[2 + thread] >= 0 && t[2 + thread] <= t[thread], "its system time within its CPU: " + t[2 + thread]);
        }
    }

    @Test
    void anAgentSideThatFailsEndsTheRunWithItsFailure() throws Exception {
        SimWorld world = LinkTestSupport.world("navigation");
        var run = new LockstepCoordinator(world, "khepera", data -> {
            if (data.step() == 3) {
                throw new AssertionError("the agent side broke");
            }
            return List.of();
        });
        // an Error on the link's reading thread, not only an exception, reaches the caller
        var e = assertThrows(IllegalStateException.class, () -> run.runFor(10));
        assertTrue(e.getMessage().contains("the agent side broke"), e.getMessage());
    }

    @Test
    void aCommandSentDuringStepKIsInEffectAtStepKPlusOne() throws Exception {
        var agent = new StopAtObstacle();
        var result = run(agent);
        long k = agent.stoppedAt;
        assertTrue(k > 0, "the robot should meet red1 ahead within 10 s");
        assertArrayEquals(new double[] {100, 100}, agent.wheels.get(1), "setSpeeds at step 0 is in effect at step 1");
        assertArrayEquals(new double[] {100, 100}, agent.wheels.get((int) k));
        assertArrayEquals(new double[] {0, 0}, agent.wheels.get((int) k + 1), "stop at step k is in effect at step k+1");
        assertTrue(result.controllerLog().contains("step " + k + " apply stop"), "applied before the world left step k");
        assertEquals(2, result.response().count(), "both commands reported as applied");
    }
}
