package jacabot.app.sweep;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.world.WorldGenerator;
import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import org.junit.jupiter.api.Test;

/** The criteria ask no more than a world physically allows. */
class PhysicalBoundsTest {
    private static WorldSpec hall(double side, String model, String walls, String rest) throws Exception {
        return WorldFileReader.parse("{ \"name\": \"hall\", \"arena\": { \"width\": " + side + ", \"depth\": " + side + " }, "
                + "\"walls\": [" + walls + "], \"boxes\": [], " + rest
                + "\"robots\": [ { \"name\": \"r\", \"model\": \"" + model + "\", \"x\": -0.5, \"z\": 0.5 } ] }", "hall.json");
    }

    @Test
    void aFourMetreHallAsksTheCoverageAMyBotCanDrive() throws Exception {
        // 600 s at 0.1 m/s: 600 cells of 10 cm of the hall's 1 600, three quarters of them
        PhysicalBounds big = PhysicalBounds.of(Experiment.OBSTACLE_AVOIDANCE, hall(4, "mybot", "", ""));
        assertEquals(0.75 * 600 / 1600, big.coverage(), 1e-9);
        assertEquals(0.5, PhysicalBounds.of(Experiment.OBSTACLE_AVOIDANCE, hall(2, "mybot", "", "")).coverage(), 1e-9);
        SuccessCriteria.Figures f = new SuccessCriteria.Figures(600, 0.5, 0.3, 0, 0, 0, false, 0, 0);
        assertTrue(SuccessCriteria.judge(Experiment.OBSTACLE_AVOIDANCE, f, big).success());
        assertEquals("coverage 30% (< 50%)", SuccessCriteria.judge(Experiment.OBSTACLE_AVOIDANCE, f).reason());
        assertEquals("coverage 20% (< 28%, the physical bound)", SuccessCriteria.judge(Experiment.OBSTACLE_AVOIDANCE,
                new SuccessCriteria.Figures(600, 0.5, 0.2, 0, 0, 0, false, 0, 0), big).reason());
    }

    /** A wall across a 2 m arena with a doorway narrower than the robot: the far half is neither floor to cover nor a place to fetch from. */
    @Test
    void aRoomTheRobotCannotEnterIsNotAskedFor() throws Exception {
        String wall = "{ \"x\": 0, \"z\": -0.52, \"size\": [0.02, 0.96] }, { \"x\": 0, \"z\": 0.52, \"size\": [0.02, 0.96] }";
        PhysicalBounds oa = PhysicalBounds.of(Experiment.OBSTACLE_AVOIDANCE, hall(2, "mybot", wall, ""));
        assertEquals(0.75 * 200 / 400, oa.coverage(), 0.02); // one room of 200 cells: 37.5 %
        String things = "\"cylinders\": [ { \"id\": \"near\", \"x\": -0.5, \"z\": -0.5 }, { \"id\": \"far\", \"x\": 0.5, \"z\": 0.5 } ], "
                + "\"storage\": { \"x\": -0.8, \"z\": 0.8, \"radius\": 0.06 }, \"charger\": { \"x\": -0.8, \"z\": -0.8, \"radius\": 0.06 }, ";
        PhysicalBounds tidy = PhysicalBounds.of(Experiment.TIDY_UP, hall(2, "khepera", wall.replace("0.96", "0.99").replace("0.52", "0.505"), things));
        assertEquals(1, tidy.storable(), "only the cylinder on the robot's side");
        assertTrue(tidy.parkable());
        var f = new SuccessCriteria.Figures(600, 0, 0, 1, 1, 0, false, 0, 0, 2, 1, true);
        assertTrue(SuccessCriteria.judge(Experiment.TIDY_UP, f, tidy).success(), SuccessCriteria.judge(Experiment.TIDY_UP, f, tidy).reason());
        assertFalse(SuccessCriteria.judge(Experiment.TIDY_UP, f).success());
        // the same world with a doorway the Khepera passes: both cylinders are asked for
        PhysicalBounds open = PhysicalBounds.of(Experiment.TIDY_UP, hall(2, "khepera", wall, things));
        assertEquals(2, open.storable());
        assertFalse(SuccessCriteria.judge(Experiment.TIDY_UP, f, open).success());
    }

    /** Navigation in the thesis' range: the bound never lowers the two deliveries. */
    @Test
    void theClassicRangeKeepsItsCriteria() {
        for (long seed = 1; seed <= 6; seed++) {
            WorldSpec w = new WorldGenerator(Experiment.NAVIGATION, seed).generate().spec();
            assertTrue(PhysicalBounds.of(Experiment.NAVIGATION, w).deliveries() >= SuccessCriteria.MIN_DELIVERIES, w.name());
        }
    }

    private static WorldSpec tidyHall(double chargerX, double chargerZ, double battery) throws Exception {
        StringBuilder cylinders = new StringBuilder();
        for (int i = 0; i < 6; i++) {
            cylinders.append(i == 0 ? "" : ", ").append("{ \"id\": \"red").append(i).append("\", \"x\": ").append(0.6 - 0.05 * i)
                    .append(", \"z\": 1.3 }");
        }
        return WorldFileReader.parse("{ \"name\": \"hall\", \"arena\": { \"width\": 3, \"depth\": 3 }, \"walls\": [], \"boxes\": [], "
                + "\"cylinders\": [" + cylinders + "], \"storage\": { \"x\": -1.3, \"z\": 1.3, \"radius\": 0.06 }, "
                + "\"charger\": { \"x\": " + chargerX + ", \"z\": " + chargerZ + ", \"radius\": 0.06, \"power\": 20 }, "
                + "\"robots\": [ { \"name\": \"r\", \"model\": \"khepera\", \"x\": 0, \"z\": 0, \"battery\": " + battery + " } ] }", "hall.json");
    }

    /**
     * Six cylinders 1.6-1.9 m from the storage point: about 21 m of tour, over 1 000 J at the Khepera's
     * 0.5 W idle and 2 W driving, so a charge on the way whatever the battery at the start. With the
     * charger beside the storage point the charge costs only its time; with the charger in the far
     * corner the way there too, and one cylinder fewer fits (the bound as it was asked for all six).
     */
    @Test
    void aTourThatOutrunsTheBatteryPaysForTheChargeAndTheWayToTheCharger() throws Exception {
        PhysicalBounds near = PhysicalBounds.of(Experiment.TIDY_UP, tidyHall(-1.2, 1.3, 560));
        PhysicalBounds far = PhysicalBounds.of(Experiment.TIDY_UP, tidyHall(1.3, -1.3, 560));
        assertEquals(6, near.storable());
        assertTrue(near.parkable());
        assertEquals(5, far.storable(), "the way to the far charger and the charge leave no time for the sixth");
        assertFalse(far.parkable());
        // navigation's bound does not count the charger (its task does not include it) but counts the
        // battery: 560 J less 300 J standing leave 6.5 m at 40 J a metre, two of the six deliveries
        assertEquals(2, PhysicalBounds.of(Experiment.NAVIGATION, tidyHall(1.3, -1.3, 560)).deliveries());
        assertEquals(6, PhysicalBounds.of(Experiment.SUSPEND_RESUME, tidyHall(1.3, -1.3, 560)).deliveries());
    }
}
