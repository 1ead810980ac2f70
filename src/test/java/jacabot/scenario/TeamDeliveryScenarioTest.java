package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.run.AgentSource;
import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.app.world.TeamWorld;
import jacabot.app.world.WorldGenerator;
import jacabot.robot.run.RunSummary;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Team delivery (thesis Chapter 6). A generated world where a claim released twice stopped the team,
 * and an agent whose reasoning runs away within a step. Two Kheperas and their agents on the packaged team world, ten
 * simulated minutes in lockstep, against the procedural team on the same world and seed. Both
 * robots deliver, the team delivers more than the team without coordination, no cylinder ever has
 * two claimers (ground truth: the cylinder a claim's robot carries, else the one nearest its place),
 * and the robots take turns at the charger.
 */
class TeamDeliveryScenarioTest {
    private static final PrintStream QUIET = new PrintStream(OutputStream.nullOutputStream());

    /**
     * Generated team world 80, two robots, seed 2: at 95 s khepera2 gave up a homing as its battery
     * ran low, and both plans that release a claim released claim 5; the second release failed in
     * the recharge trip's atomic start, which ran the failed action again every reasoning cycle, and
     * the lockstep step never ended. A claim is now released once, and an atomic plan's failed action
     * goes to its failure plan (Jason's rule): the run goes on.
     */
    @Test
    void aClaimReleasedTwiceAsTheBatteryRunsLowDoesNotStopTheTeam() throws Exception {
        WorldSpec spec = WorldGenerator.team(2, 80).generate().spec();
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");
        var run = TeamDeliveryRun.agents(spec, agent, 2, 100, QUIET, false, null);
        assertTrue(run.agentFailure().isEmpty(), run.agentFailure().toString());
        assertEquals(100, run.figures().duration(), 0.05);
    }

    /** One robot's agent loops within a step: the team's run ends at that step, naming it. */
    @Test
    void anAgentWhoseReasoningRunsAwayEndsTheTeamsRunNamingIt() throws Exception {
        WorldSpec spec = WorldGenerator.team(2, 80).generate().spec();
        AgentSource agent = AgentSource.text("spinner.asl", """
                !start.
                +!start : .my_name(khepera2) <- !spin.
                +!start <- .wait(60000).
                @spin +!spin <- !spin.
                """);
        var run = TeamDeliveryRun.agents(spec, agent, 2, 60, QUIET, false, null);
        assertTrue(run.agentFailure().orElseThrow().startsWith("khepera2: reasoning ran away in control step 0 at t=0.00 s"),
                run.agentFailure().toString());
        assertTrue(run.figures().duration() < 1, "ended at once: " + run.figures().duration() + " s");
    }

    @Tag("long")
    @Test
    void twoCoordinatedRobotsDeliverMoreThanTwoWithoutCoordination() throws Exception {
        WorldSpec spec = TeamWorld.firstRobots(WorldFileReader.read(
                Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json")), 2);
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");
        var agents = TeamDeliveryRun.agents(spec, agent, spec.seed(), 600, QUIET, false, null);
        var baseline = TeamDeliveryRun.baseline(spec, spec.seed(), 600);
        String figures = agents.robots().stream().map(RunSummary::toText).reduce("", String::concat)
                + "\nbaseline: " + baseline.deliveries() + " deliveries";
        assertTrue(agents.agentFailure().isEmpty(), () -> agents.agentFailure() + "\n" + figures);
        assertEquals(600, agents.figures().duration(), 0.05, figures);
        for (RunSummary r : agents.robots()) {
            assertTrue(r.deliveries() >= 1, r.robot() + " delivered\n" + figures);
        }
        assertTrue(agents.deliveries() > baseline.deliveries(), figures);
        assertTrue(agents.claims() > 0, "the agents claimed cylinders\n" + figures);
        assertEquals(0, agents.figures().doubleClaims(), figures);
        assertTrue(agents.robots().stream().mapToInt(RunSummary::chargerVisits).sum() >= 1, "a robot recharged\n" + figures);
    }
}
