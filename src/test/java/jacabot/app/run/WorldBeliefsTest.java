package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.syntax.Literal;
import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

class WorldBeliefsTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void theLandmarksOfTheWorldFileBecomeBeliefs() throws Exception {
        WorldSpec w = WorldFileReader.read(ROOT.resolve(Experiment.SUSPEND_RESUME.worldFile()));
        List<String> beliefs = WorldBeliefs.of(w).stream().map(Literal::toString).toList();
        assertEquals(List.of("arena(" + num(w.arena().width()) + "," + num(w.arena().depth()) + ")",
                "storagePoint(" + num(w.storage().x()) + "," + num(w.storage().z()) + ")",
                "storageRadius(" + num(w.storage().radius()) + ")",
                "charger(" + num(w.charger().x()) + "," + num(w.charger().z()) + ")"), beliefs);
    }

    @Test
    void aWorldWithoutStorageGivesNoStorageBeliefs() throws Exception {
        WorldSpec w = WorldFileReader.read(ROOT.resolve(Experiment.OBSTACLE_AVOIDANCE.worldFile()));
        List<String> beliefs = WorldBeliefs.of(w).stream().map(Literal::toString).toList();
        assertEquals(List.of("arena(" + num(w.arena().width()) + "," + num(w.arena().depth()) + ")"), beliefs);
    }

    private static String num(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v);
    }
}
