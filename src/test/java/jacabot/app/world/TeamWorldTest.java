package jacabot.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.RobotSpec;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class TeamWorldTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void aTeamOfNKeepsTheFirstNRobots() throws Exception {
        WorldSpec w = WorldFileReader.read(ROOT.resolve("worlds/team-delivery.json"));
        assertEquals(4, w.robots().size());
        for (int n = 1; n <= 4; n++) {
            assertEquals(Optional.empty(), TeamWorld.missing(w, n, "team.json"));
            WorldSpec team = TeamWorld.firstRobots(w, n);
            assertEquals(w.robots().subList(0, n), team.robots());
            assertEquals(w.cylinders(), team.cylinders());
        }
        assertEquals(Optional.of("team.json: $.robots: the team-delivery experiment with 5 robots needs as many; the world has 4"),
                TeamWorld.missing(w, 5, "team.json"));
        assertThrows(IllegalArgumentException.class, () -> TeamWorld.firstRobots(w, 5));
    }

    @Test
    void aTeamNeedsKheperasAStoragePointAndACharger() throws Exception {
        WorldSpec nav = WorldFileReader.read(ROOT.resolve("worlds/navigation.json"));
        assertEquals(Optional.of("n.json: $.charger: the team-delivery experiment needs a charger; the world has none"),
                TeamWorld.missing(nav, 1, "n.json"));
        WorldSpec mybot = WorldFileReader.read(ROOT.resolve("worlds/obstacle-avoidance.json"));
        assertTrue(TeamWorld.missing(mybot, 1, "o.json").orElseThrow().startsWith("o.json: $.robots[0].model: "));
    }

    @Test
    void anEventNamingARobotLeftOutIsRefused() throws Exception {
        WorldSpec w = WorldFileReader.parse("{ \"arena\": {\"width\": 1, \"depth\": 1}, \"robots\": ["
                + "{\"name\": \"k1\", \"model\": \"khepera\", \"x\": 0, \"z\": 0}, {\"name\": \"k2\", \"model\": \"khepera\", \"x\": 0.3, \"z\": 0}],"
                + " \"events\": [{\"at\": 5, \"do\": \"drain\", \"robot\": \"k2\", \"amount\": 10}] }", "t.json");
        assertEquals(List.of("k1", "k2"), TeamWorld.firstRobots(w, 2).robots().stream().map(RobotSpec::name).toList());
        assertEquals("an event of the world t.json names robot 'k2', which a team of 1 leaves out",
                assertThrows(IllegalArgumentException.class, () -> TeamWorld.firstRobots(w, 1)).getMessage());
    }
}
