package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.sim.geom.Pose;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Experiment 4 (thesis Chapter 4 §4, Appendix B): on a low battery the robot suspends what it
 * does, recharges at the charger, comes back to the marked point and resumes. Measured with
 * {@code jacabot experiment suspend-resume --headless --seed 4 --duration 300s}: low at 60 s,
 * charged at 127 s, back at the marked point at 190 s, lowest battery 409 J.
 */
class SuspendResumeScenarioTest {
    /** How far from the marked point the robot may stop (3 cm threshold per axis, GPS in cm). */
    static final double BACK_WITHIN = 0.06;

    @Test
    void rechargesAndComesBackToTheMarkedPoint() throws Exception {
        checkRecharge(4, false, 300);
    }

    @Tag("long")
    @ParameterizedTest(name = "seed {0}, noise {1}")
    @CsvSource({"2, false, 400", "4, true, 400"})
    void rechargesWithOtherSeeds(long seed, boolean noise, int seconds) throws Exception {
        checkRecharge(seed, noise, seconds);
    }

    private static void checkRecharge(long seed, boolean noise, int seconds) throws Exception {
        ScenarioRun run = ScenarioRun.run(Experiment.SUSPEND_RESUME, seed, noise, seconds);
        assertTrue(run.minBattery() > 0, run.summary());
        long low = run.firstLine("Battery low!", 0);
        long charged = run.firstLine("RECHARGED", low);
        long back = run.firstLine("Previous pt reached", charged);
        assertTrue(low >= 0 && charged > low && back > charged, run.summary());
        AreaSpec charger = run.world.spec().charger();
        Pose atCharger = run.at(charged).pose();
        assertTrue(Math.hypot(atCharger.x() - charger.x(), atCharger.z() - charger.z()) < charger.radius(), "on the charger: " + atCharger);
        assertTrue(run.at(charged).battery() >= 850, run.summary());
        Pose marked = run.at(low).pose();
        Pose returned = run.at(back).pose();
        double off = Math.hypot(marked.x() - returned.x(), marked.z() - returned.z());
        assertTrue(off <= BACK_WITHIN, "back " + off + " m from the marked point; " + run.summary());
    }

    /**
     * What {@code gradle run} shows, under the world file's own seed: the battery runs low during a
     * delivery (Appendix B's "Almost reached" path), the robot recharges, comes back to the marked
     * point, restores its state and completes the delivery. Measured (seed 13): picked at 42 s, low
     * at 68 s, recharged at 151 s, delivered at 201 s. With the recovery plans (not in the thesis), this timing is the agent as
     * published (as-published/suspend-resume.asl); the default agent travels faster and delivers
     * before the battery runs low on this seed (completesTheDeliveryInterruptedByALowBattery checks
     * the suspended delivery for it).
     */
    @Test
    void theDefaultRunSuspendsADeliveryAndCompletesIt() throws Exception {
        WorldSpec world = WorldFileReader.read(ScenarioRun.ROOT.resolve(Experiment.SUSPEND_RESUME.worldFile()));
        ScenarioRun run = ScenarioRun.runPublished(Experiment.SUSPEND_RESUME, world.seed(), world.sensorNoise(), 240);
        long picked = run.firstLine("Cylinder picked up", 0);
        assertTrue(picked >= 0, run.summary());
        Suspension s = assertDeliverySuspendedAndCompleted(run, picked);
        long restart = run.firstLine("Restart delivering", s.back());
        assertTrue(s.low() > picked && restart >= s.back(), run.summary());
        assertTrue(run.releases.stream().anyMatch(r -> r.inStorage() && r.timeMs() > restart), "delivered after resuming: " + run.summary());
    }

    /** The battery runs low right after a pick (a supervisor sets it to 490 J): the delivery is suspended and completed. */
    @Test
    void completesTheDeliveryInterruptedByALowBattery() throws Exception {
        checkInterruptedDelivery(3, false);
    }

    @Tag("long")
    @ParameterizedTest(name = "seed {0}, noise {1}")
    @CsvSource({"1, false", "3, true"})
    void completesTheInterruptedDeliveryWithOtherSeeds(long seed, boolean noise) throws Exception {
        checkInterruptedDelivery(seed, noise);
    }

    private static void checkInterruptedDelivery(long seed, boolean noise) throws Exception {
        long[] drainedAt = {-1};
        UnaryOperator<WorldSpec> fullBattery = s -> {
            RobotSpec r = s.robots().get(0);
            return new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), s.seed(), s.sensorNoise(), s.walls(),
                    s.boxes(), s.cylinders(), s.storage(), s.charger(),
                    List.of(new RobotSpec(r.name(), r.model(), r.x(), r.z(), r.heading(), 1000)), s.events());
        };
        ScenarioRun run = ScenarioRun.run(Experiment.SUSPEND_RESUME, seed, noise, 420, fullBattery, (t, r) -> {
            long picked = r.firstLine("Cylinder picked up", 0);
            if (drainedAt[0] < 0 && picked >= 0 && t >= picked + 1000) {
                r.world.supervisor().setBattery("khepera", 490);
                drainedAt[0] = t;
            }
        });
        assertTrue(drainedAt[0] > 0, run.summary());
        assertTrue(run.minBattery() > 0, run.summary());
        assertDeliverySuspendedAndCompleted(run, drainedAt[0]);
    }

    /** When the battery ran low, when the robot was recharged, when it was back at the marked point (ms). */
    private record Suspension(long low, long charged, long back) {
    }

    /**
     * From {@code fromMs}: the battery runs low while the robot carries a cylinder, it recharges with
     * the cylinder, comes back to the marked point and then delivers, never entering the storage
     * area empty-handed.
     */
    private static Suspension assertDeliverySuspendedAndCompleted(ScenarioRun run, long fromMs) {
        long low = run.firstLine("Battery low!", fromMs);
        long charged = run.firstLine("RECHARGED", low);
        long back = run.firstLine("Previous pt reached", charged);
        assertTrue(low >= 0 && charged > low && back > charged, run.summary());
        assertTrue(run.at(low).carried() != null && run.at(charged).carried() != null, "carried while charging: " + run.summary());
        assertTrue(run.releases.stream().anyMatch(r -> r.inStorage() && r.timeMs() > back), "delivered after resuming: " + run.summary());
        NavigationScenarioTest.assertNeverBackWithoutACylinder(run);
        return new Suspension(low, charged, back);
    }
}
