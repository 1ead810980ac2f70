package jacabot.robot.baseline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.util.List;
import org.junit.jupiter.api.Test;

/** N copies of experiment 4's baseline in one world, each on its thread, the world stepped once per step for all. */
class TeamBaselineTest {
    /** The team world with its first {@code n} robots, under {@code seed}. */
    private static SimWorld team(int n, long seed) throws Exception {
        WorldSpec s = WorldFileReader.read(BaselinesTest.worlds().resolve("team-delivery.json"));
        return SimWorld.of(new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), seed, s.sensorNoise(),
                s.walls(), s.boxes(), s.cylinders(), s.storage(), s.charger(), s.robots().subList(0, n), s.events()));
    }

    @Test
    void aTeamOfOneIsTheSingleBaseline() throws Exception {
        TeamBaseline.TeamRun team = TeamBaseline.run(team(1, 3), 3, 30);
        SimWorld world = team(1, 3);
        RunRecorder alone = RunRecorder.attach(world, "khepera1");
        new SuspendResumeBaseline(world, "khepera1", 3, alone::note).runFor(30);
        assertEquals(alone.events(), team.recorders().get(0).events());
        assertEquals(alone.trajectory(), team.recorders().get(0).trajectory());
        assertEquals(30.0, team.world().time(), 1e-9);
    }

    @Test
    void aTeamRunIsTheSameWhateverTheThreadsTiming() throws Exception {
        TeamBaseline.TeamRun a = TeamBaseline.run(team(3, 5), 5, 30);
        TeamBaseline.TeamRun b = TeamBaseline.run(team(3, 5), 5, 30);
        assertEquals(3, a.summaries().size());
        for (int i = 0; i < 3; i++) {
            assertEquals(a.recorders().get(i).trajectory(), b.recorders().get(i).trajectory(), "robot " + (i + 1));
            assertEquals(a.recorders().get(i).events(), b.recorders().get(i).events(), "robot " + (i + 1));
        }
        List<?> first = a.recorders().get(0).trajectory(), second = a.recorders().get(1).trajectory();
        assertNotEquals(first.get(first.size() - 1), second.get(second.size() - 1), "each robot drives its own way");
        assertTrue(a.recorders().get(1).trajectory().size() > 700, "a pose of robot 2 per control step of the 30 s");
        assertEquals(a.recorders().get(0).trajectory().size(), a.recorders().get(2).trajectory().size());
    }
}
