package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.sweep.EndState;
import jacabot.robot.Experiment;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Tidy-up (not in the thesis, an agent composed of the skills of Chapter 4): in its world, every
 * cylinder ends in the storage area, and then the robot parks on the charger (tidy-up's success
 * criterion, read from the world as the sweep reads it). A whole task of ten simulated minutes:
 * tagged long.
 */
class TidyUpScenarioTest {
    @Tag("long")
    @Test
    void storesEveryCylinderThenParksOnTheCharger() throws Exception {
        ScenarioRun run = ScenarioRun.run(Experiment.TIDY_UP, 17, false, 600);
        EndState end;
        synchronized (run.world) {
            end = EndState.of(run.world.snapshot(), Experiment.TIDY_UP.robot());
        }
        assertEquals(run.world.spec().cylinders().size(), end.stored(), "cylinders in the storage area; " + run.summary());
        long parking = run.firstLine("parking on the charger", 0);
        assertTrue(parking >= 0 && run.firstLine("Parked on the charger", parking) > parking, run.summary());
        assertTrue(end.parked(), "on the charger at the end; " + run.summary());
        assertTrue(run.minBattery() > 0, run.summary());
    }
}
