package jacabot.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class LandmarksTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void theDefaultWorldsLoadAndHaveWhatTheirExperimentNeeds() throws Exception {
        for (Experiment e : Experiment.values()) {
            WorldSpec w = WorldFileReader.read(ROOT.resolve(e.worldFile()));
            assertEquals(Optional.empty(), Landmarks.missing(e, w, e.worldFile()));
        }
    }

    @Test
    void eachMissingEntryIsNamed() throws Exception {
        WorldSpec w = WorldFileReader.read(ROOT.resolve(Experiment.SUSPEND_RESUME.worldFile()));
        WorldSpec noStorage = new WorldSpec(w.name(), w.arena(), w.basicTimeStep(), w.controlStep(), w.seed(), w.sensorNoise(),
                w.walls(), w.boxes(), w.cylinders(), null, w.charger(), w.robots(), w.events());
        WorldSpec noCharger = new WorldSpec(w.name(), w.arena(), w.basicTimeStep(), w.controlStep(), w.seed(), w.sensorNoise(),
                w.walls(), w.boxes(), w.cylinders(), w.storage(), null, w.robots(), w.events());
        WorldSpec noRobot = new WorldSpec(w.name(), w.arena(), w.basicTimeStep(), w.controlStep(), w.seed(), w.sensorNoise(),
                w.walls(), w.boxes(), w.cylinders(), w.storage(), w.charger(), List.of(), List.of());
        assertEquals("f.json: $.storage: the navigation experiment needs a storage point; the world has none",
                Landmarks.missing(Experiment.NAVIGATION, noStorage, "f.json").orElseThrow());
        assertEquals(Optional.empty(), Landmarks.missing(Experiment.NAVIGATION, noCharger, "f.json"));
        assertEquals("f.json: $.charger: the suspend-resume experiment needs a charger; the world has none",
                Landmarks.missing(Experiment.SUSPEND_RESUME, noCharger, "f.json").orElseThrow());
        assertTrue(Landmarks.missing(Experiment.OBJECT_PICKING, noRobot, "f.json").orElseThrow()
                .startsWith("f.json: $.robots: the object-picking experiment needs a robot named 'khepera'"));
        assertEquals(Optional.empty(), Landmarks.missing(Experiment.OBJECT_PICKING, noStorage, "f.json"));
    }
}
