package jacabot.robot.baseline;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import org.junit.jupiter.api.Test;

/** The equal-capability baselines use the agents' strategies where the thesis' programs do not. */
class EqualCapabilityBaselineTest {
    private static RunSummary run(Experiment e, long seed, double seconds, boolean equal) throws WorldFileException {
        SimWorld world = BaselineRunner.load(e.worldFile(BaselinesTest.worlds()), seed);
        RunRecorder rec = RunRecorder.attach(world, e.robot());
        BaselineController c = equal ? BaselineRunner.createEqual(e, world, seed, rec::note) : BaselineRunner.create(e, world, seed, rec::note);
        c.runFor(seconds);
        return rec.summary(equal ? "equal" : "baseline");
    }

    @Test
    void theEqualBaselineIsTheThesisProgramWithTheAgentsStrategies() throws WorldFileException {
        SimWorld world = BaselineRunner.load(Experiment.NAVIGATION.worldFile(BaselinesTest.worlds()), 1);
        assertFalse(((ObjectPickingBaseline) BaselineRunner.create(Experiment.NAVIGATION, world, 1, l -> { })).hasEqualCapabilities());
        BaselineController equal = BaselineRunner.createEqual(Experiment.NAVIGATION, world, 1, l -> { });
        assertTrue(equal instanceof NavigationBaseline && ((ObjectPickingBaseline) equal).hasEqualCapabilities());
        SimWorld hall = BaselineRunner.load(Experiment.OBSTACLE_AVOIDANCE.worldFile(BaselinesTest.worlds()), 1);
        assertTrue(BaselineRunner.createEqual(Experiment.OBSTACLE_AVOIDANCE, hall, 1, l -> { }) instanceof EqualObstacleAvoidanceBaseline);
    }

    /** Navigation's world, 3 minutes: far sight and the sweep deliver at least as often as the thesis' random walk. */
    @Test
    void navigationDeliversWithFarSightAndTheSweep() throws WorldFileException {
        RunSummary equal = run(Experiment.NAVIGATION, 1, 180, true);
        RunSummary thesis = run(Experiment.NAVIGATION, 1, 180, false);
        assertTrue(equal.deliveries() >= 1 && equal.deliveries() >= thesis.deliveries(), equal.toText() + "\n" + thesis.toText());
        assertTrue(equal.storageEntriesEmpty() == 0, equal.eventLog());
    }

    /** Obstacle avoidance's world, 5 minutes: dead-reckoned turns to new floor cover more than random motion, touching little. */
    @Test
    void obstacleAvoidanceCoversWithDeadReckoning() throws WorldFileException {
        RunSummary equal = run(Experiment.OBSTACLE_AVOIDANCE, 1, 300, true);
        RunSummary thesis = run(Experiment.OBSTACLE_AVOIDANCE, 1, 300, false);
        assertTrue(equal.coverage() > thesis.coverage() && equal.contactTime() < 2, equal.toText() + "\n" + thesis.toText());
    }
}
