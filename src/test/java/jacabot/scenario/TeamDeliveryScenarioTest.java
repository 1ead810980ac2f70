package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.run.AgentSource;
import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.app.world.TeamWorld;
import jacabot.robot.run.RunSummary;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Team delivery (thesis Chapter 6): two Kheperas and their agents on the packaged team world, ten
 * simulated minutes in lockstep, against the procedural team on the same world and seed. Both
 * robots deliver, the team delivers more than the team without coordination, no cylinder ever has
 * two claimers (ground truth: the cylinder a claim's robot carries, else the one nearest its place),
 * and the robots take turns at the charger.
 */
class TeamDeliveryScenarioTest {
    @Tag("long")
    @Test
    void twoCoordinatedRobotsDeliverMoreThanTwoWithoutCoordination() throws Exception {
        WorldSpec spec = TeamWorld.firstRobots(WorldFileReader.read(
                Path.of(System.getProperty("jacabot.rootDir", "."), "worlds/team-delivery.json")), 2);
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "team-delivery.asl");
        var agents = TeamDeliveryRun.agents(spec, agent, spec.seed(), 600, new PrintStream(OutputStream.nullOutputStream()),
                false, null);
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
