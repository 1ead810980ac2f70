package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.robot.Experiment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SweepPlanTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    /** A folder of worlds swept for one experiment takes the files named for none, but not a team's. */
    @Test
    void aTeamWorldIsNotSweptForOneRobot(@TempDir Path dir) throws Exception {
        Files.copy(ROOT.resolve("worlds/navigation.json"), dir.resolve("my-world.json"));
        Files.copy(ROOT.resolve("worlds/navigation.json"), dir.resolve("navigation.json"));
        Files.copy(ROOT.resolve("worlds/team-delivery.json"), dir.resolve("team-delivery.json"));
        List<SweepPlan.World> worlds = SweepPlan.directory(List.of(Experiment.NAVIGATION), dir);
        assertEquals(List.of("my-world", "navigation"), worlds.stream().map(SweepPlan.World::name).toList());
    }
}
