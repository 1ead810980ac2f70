package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Tidy-up's end state read from the world: cylinders in the storage area, the robot on the charger. */
class EndStateTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void theWorldAsItStartsHasNothingStoredAndNobodyParked() throws Exception {
        SimWorld w = SimWorld.load(ROOT.resolve(Experiment.TIDY_UP.worldFile()));
        assertEquals(new EndState(4, 0, false), EndState.of(w.snapshot(), Experiment.TIDY_UP.robot()));
    }

    @Test
    void cylindersInTheStorageAreaAndTheRobotOnTheChargerCount() throws Exception {
        SimWorld w = SimWorld.load(ROOT.resolve(Experiment.TIDY_UP.worldFile()));
        var storage = w.spec().storage();
        var charger = w.spec().charger();
        w.supervisor().move("red1", storage.x() + 0.02, storage.z());
        w.supervisor().move("red2", storage.x(), storage.z() - 0.03);
        w.supervisor().move("red3", storage.x() + 0.2, storage.z()); // next to the area, not in it
        w.supervisor().move(Experiment.TIDY_UP.robot(), charger.x(), charger.z() + 0.03);
        assertEquals(new EndState(4, 2, true), EndState.of(w.snapshot(), Experiment.TIDY_UP.robot()));
    }
}
