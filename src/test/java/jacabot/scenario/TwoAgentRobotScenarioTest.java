package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.run.AgentSource;
import jacabot.app.run.RobotAgent;
import jacabot.robot.Experiment;
import jacabot.sim.geom.Pose;
import jacabot.sim.world.AreaSpec;
import java.util.ArrayList;
import java.util.List;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * One robot, two agents (the thesis' Chapter 6 wish) on experiment 4's world: the task agent
 * searches, picks and delivers; on a low battery the energy agent suspends it, takes the wheels,
 * recharges the robot and hands the wheels and the task back. At no control step do the
 * commands of both agents reach the wheels.
 */
class TwoAgentRobotScenarioTest {
    /** The control steps at which each agent's wheel commands went through. */
    record Drivers(List<Long> task, List<Long> energy, List<Long> both) {
    }

    static List<RobotAgent> taskAndEnergy() {
        return List.of(agent("task"), agent("energy"));
    }

    private static RobotAgent agent(String name) {
        String file = "suspend-resume-" + name + ".asl";
        return new RobotAgent(name, AgentSource.resource("/asl/" + file, file));
    }

    @Test
    void theEnergyAgentSuspendsTheTaskRechargesAndResumesIt() throws Exception {
        check(13, 330);
    }

    @Tag("long")
    @ParameterizedTest(name = "seed {0}")
    @CsvSource({"4, 400", "2, 400"})
    void withOtherSeeds(long seed, int seconds) throws Exception {
        check(seed, seconds);
    }

    /** Two agents, one lockstep run: still a pure function of world file and seed, to every pose and console line. */
    @Tag("long")
    @Test
    void theSameWorldAndSeedGiveTheSameRun() throws Exception {
        ScenarioRun one = ScenarioRun.run(Experiment.SUSPEND_RESUME, taskAndEnergy(), 13, false, 120, UnaryOperator.identity(),
                (t, r) -> {
                });
        ScenarioRun two = ScenarioRun.run(Experiment.SUSPEND_RESUME, taskAndEnergy(), 13, false, 120, UnaryOperator.identity(),
                (t, r) -> {
                });
        assertTrue(one.firstLine("Task suspended", 0) > 0, one.summary());
        assertEquals(one.samples, two.samples);
        assertEquals(one.lines, two.lines);
    }

    private static void check(long seed, int seconds) throws Exception {
        var drivers = new Drivers(new ArrayList<>(), new ArrayList<>(), new ArrayList<>());
        ScenarioRun run = ScenarioRun.run(Experiment.SUSPEND_RESUME, taskAndEnergy(), seed, false, seconds,
                UnaryOperator.identity(), (t, r) -> {
                    List<String> now = r.lockstep.middleware().wheelLease().drivers();
                    if (now.contains("task")) {
                        drivers.task().add(t);
                    }
                    if (now.contains("energy")) {
                        drivers.energy().add(t);
                    }
                    if (now.size() > 1) {
                        drivers.both().add(t);
                    }
                });
        assertTrue(run.lockstep.agentFailure().isEmpty(), run.lockstep.agentFailure() + "; " + run.summary());
        // the energy agent says "Battery low!" once it has the wheels: after the task has let them go;
        // a line carries the time of the step before the one it was printed in
        long step = run.world.controlStep();
        long suspended = run.firstLine("Task suspended", 0) + step;
        long low = run.firstLine("Battery low!", 0);
        long charged = run.firstLine("RECHARGED", suspended);
        long back = run.firstLine("Previous pt reached", charged);
        long resumed = run.firstLine("Task resumed", back) + step;
        assertTrue(suspended > 0 && low >= suspended - step && charged > low && back > charged && resumed >= back,
                "suspended " + suspended + ", low " + low + ", charged " + charged + ", back " + back + ", resumed " + resumed
                        + "; " + run.summary());
        AreaSpec charger = run.world.spec().charger();
        Pose atCharger = run.at(charged).pose();
        assertTrue(Math.hypot(atCharger.x() - charger.x(), atCharger.z() - charger.z()) < charger.radius(), "on the charger: " + atCharger);
        assertTrue(run.at(charged).battery() >= 850, run.summary());
        assertEquals(List.of(), drivers.both(), "steps at which both agents commanded the wheels");
        // the wheels were the task's before and after, the energy agent's only in between
        assertTrue(drivers.task().stream().anyMatch(t -> t < suspended) && drivers.task().stream().anyMatch(t -> t > resumed),
                "the task drove");
        assertTrue(drivers.energy().stream().allMatch(t -> t > suspended && t < resumed), "the energy agent drove outside its trip: "
                + drivers.energy());
        assertTrue(drivers.task().stream().noneMatch(t -> t > suspended && t < resumed), "the task drove while suspended: "
                + drivers.task().stream().filter(t -> t > suspended && t < resumed).toList() + " " + suspended + ".." + resumed);
        assertTrue(drivers.energy().stream().anyMatch(t -> t < charged), "the energy agent drove to the charger");
        assertTrue(drivers.energy().stream().anyMatch(t -> t > charged), "the energy agent drove back");
        assertTrue(run.deliveries() >= 1, run.summary());
    }
}
