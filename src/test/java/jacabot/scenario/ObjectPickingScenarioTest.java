package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Experiment 2 (thesis Chapter 4 §2): the Khepera finds and lifts the red cylinder, and copes with
 * it being moved away during the grip and knocked out of the gripper. Measured pick times (no
 * noise): seed 1 26 s, 3 21 s, 2 120 s, 8 163 s; seeds 4 and 6 never come near it in 180 s
 * (random motion: the camera sees red only within about 10 cm).
 */
class ObjectPickingScenarioTest {
    @Test
    void picksTheRedCylinderWithinAMinute() throws Exception {
        checkPicked(1, false, 60);
    }

    @Tag("long")
    @ParameterizedTest(name = "seed {0}, noise {1}, within {2} s")
    @CsvSource({"3, false, 60", "2, false, 180", "8, false, 180", "1, true, 60"})
    void picksWithOtherSeeds(long seed, boolean noise, int seconds) throws Exception {
        checkPicked(seed, noise, seconds);
    }

    private static void checkPicked(long seed, boolean noise, int seconds) throws Exception {
        ScenarioRun run = ScenarioRun.run(Experiment.OBJECT_PICKING, seed, noise, seconds);
        assertEquals("red1", run.world.supervisor().carried("khepera"), run.summary());
        assertTrue(run.firstLine("Cylinder picked up", 0) >= 0, run.summary());
        assertTrue(run.robot.getGripper().isArmUp(), "the arm is up: " + run.summary());
    }

    @Test
    void aCylinderMovedAwayDuringTheGripTimesOutAndTheRobotWandersOn() throws Exception {
        long[] movedAt = {-1};
        ScenarioRun run = ScenarioRun.run(Experiment.OBJECT_PICKING, 1, false, 70, UnaryOperator.identity(), (t, r) -> {
            if (movedAt[0] < 0 && r.firstLine("Cylinder detected", 0) >= 0) {
                r.world.supervisor().move("red1", -0.4, -0.4);
                movedAt[0] = t;
            }
        });
        assertTrue(movedAt[0] > 0, run.summary());
        long notFound = run.firstLine("Cylinder not found", movedAt[0]);
        assertTrue(notFound > movedAt[0] && notFound - movedAt[0] <= 8000, "grip timeout at " + notFound + "; " + run.summary());
        // nothing picked at the grip; far sight (not in the thesis) may find the moved cylinder again later
        long picked = run.firstLine("Cylinder picked up", 0);
        assertTrue(picked < 0 || picked > notFound + 3000, "picked at " + picked + "; " + run.summary());
        assertTrue(run.travelled(notFound + 3000, notFound + 23_000) > 0.3, "wanders on: " + run.summary());
    }

    /** The thesis' behaviour, kept in the agent as published (recovery, not in the thesis: the default agent lets the cylinder go and wanders on). */
    @Test
    void aCylinderKnockedOutOfTheGripperStopsTheRobotWithAReport() throws Exception {
        long[] knockedAt = {-1};
        ScenarioRun run = ScenarioRun.runPublished(Experiment.OBJECT_PICKING, 1, false, 60, UnaryOperator.identity(), (t, r) -> {
            long picked = r.firstLine("Cylinder picked up", 0);
            if (knockedAt[0] < 0 && picked >= 0 && t >= picked + 3000) {
                assertTrue(r.world.supervisor().knockCarried("khepera"));
                knockedAt[0] = t;
            }
        });
        assertTrue(knockedAt[0] > 0, run.summary());
        long report = run.firstLine("[robot] Cylinder has fallen. Anybody retrieve it", knockedAt[0]);
        assertTrue(report >= 0 && report - knockedAt[0] <= 200, "report at " + report + "; " + run.summary());
        assertTrue(run.travelled(report + 200, 60_000) < 0.002, "stopped: " + run.summary());
        assertNull(run.world.supervisor().carried("khepera"));
    }
}
