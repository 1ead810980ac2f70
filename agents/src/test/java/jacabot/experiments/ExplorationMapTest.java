package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ExplorationMapTest {
    /** The MyBot: 1 mm/s per speed unit, 9 cm between the wheels. */
    private final ExplorationMap map = new ExplorationMap(0.001, 0.09);

    @Test
    void deadReckoningIntegratesTheWheelSpeedsInEffect() {
        map.wheels(0, 100, 100);
        map.wheels(2000, 100, 100); // 2 s at 0.1 m/s
        assertEquals(0.2, map.x(), 1e-9);
        assertEquals(0.0, map.z(), 1e-9);
        map.wheels(2000, -50, 50);
        // left turn: (0.05 + 0.05) / 0.09 rad/s for the time of a quarter turn
        long quarter = Math.round(1000 * (Math.PI / 2) / (0.1 / 0.09));
        map.wheels(2000 + quarter, 0, 0);
        assertEquals(90, map.headingDegrees(), 0.5);
        assertEquals(0.2, map.x(), 1e-9, "a turn on the spot does not move the centre");
    }

    @Test
    void theTurnPointsAtFloorNotYetCrossed() {
        // the robot has driven 1 m ahead and back: the floor ahead is known
        map.wheels(0, 100, 100);
        map.wheels(10_000, -100, -100);
        map.wheels(20_000, 0, 0);
        double turn = map.bestTurn();
        assertTrue(Math.abs(turn) >= 60, "away from the metre already crossed, got " + turn);
        // now 1 m behind and back too: only the sides are new
        map.wheels(20_000, -100, -100);
        map.wheels(30_000, 100, 100);
        map.wheels(40_000, 0, 0);
        turn = map.bestTurn();
        // (a diagonal crosses more 10 cm cells per metre than a side way: any turn off the line will do)
        assertTrue(Math.abs(turn) >= 30 && Math.abs(turn) <= 150, "off the line crossed both ways, got " + turn);
    }

    @Test
    void anObstacleMarkEndsTheFloorAHeadingCanReach() {
        map.obstacle(0, 0.13);
        double turn = map.bestTurn();
        assertTrue(turn != 0, "not straight into the obstacle just met, got " + turn);
        assertTrue(map.cellsVisited() >= 1);
    }

    @Test
    void staleTimeCountsOnlyFloorCrossedBefore() {
        drive(0, 3000, 100); // 30 cm out: fresh cells all the way
        assertTrue(map.staleMillis(3000) < 1000, "the cells just entered were new, got " + map.staleMillis(3000));
        drive(3000, 5500, -100); // 25 cm back over the same cells
        assertTrue(map.staleMillis(5500) >= 2000, "over old floor since 3 s, got " + map.staleMillis(5500));
        drive(5500, 9000, -100); // past the start: new floor again
        assertTrue(map.staleMillis(9000) < 1000, "fresh floor behind the start, got " + map.staleMillis(9000));
    }

    @Test
    void freshCellsSinceCountsOnlyCellsFirstCrossedAfterThatTime() {
        drive(0, 3000, 100);     // 30 cm out: three new cells by 3 s
        drive(3000, 5500, -100); // 25 cm back over them: none new
        assertEquals(0, map.freshCellsSince(3500), "none new on the way back");
        assertEquals(3, map.freshCellsSince(0), 1);
        drive(5500, 9000, -100); // past the start: new floor again
        assertEquals(3, map.freshCellsSince(5500), 1);
    }

    @Test
    void theWayToAFrontierGoesAlongFloorCrossedToADoorwayNotIntoAWall() {
        // a lane of ten cells along x, crossed; obstacles met all round it (the walls met at 13 cm
        // leave cells between them, as here), except a doorway three cells wide in its right side
        drive(0, 9_500, 100);
        for (int i = -1; i <= 11; i++) {
            mark(i, 1);
            if (i < 4 || i > 6) {
                mark(i, -1);
            }
        }
        mark(-1, 0);
        mark(11, 0);
        double[] way = map.frontierWaypoint();
        assertTrue(way != null, "the doorway is a frontier");
        // the robot at the lane's far end (cell 9): the way runs back along the lane, 4 cells to cell 5
        assertTrue(Math.abs(way[0]) > 150, "back along the lane, got " + way[0]);
        assertEquals(0.4, way[1], 0.05);
        mark(5, -1); // the doorway closed: every cell out of the lane is next to an obstacle met
        assertNull(map.frontierWaypoint());
    }

    /** An obstacle met in cell (i, j), marked from where the robot is (heading 0, as {@code drive} leaves it). */
    private void mark(int i, int j) {
        double dx = (i + 0.5) * ExplorationMap.CELL - map.x(), dz = (j + 0.5) * ExplorationMap.CELL - map.z();
        map.obstacle(Math.toDegrees(Math.atan2(dz, dx)), Math.hypot(dx, dz));
    }

    @Test
    void aShortHorizonPrefersNearFreshFloorToFarFreshFloor() {
        drive(0, 6000, 100);      // 60 cm ahead and back: the near floor ahead is known
        drive(6000, 12000, -100);
        map.obstacle(180, 0.75);  // behind: 70 cm of new floor, then an obstacle
        for (int bearing : new int[] {30, 60, 90, 120, 150}) { // the other headings: obstacles at once
            map.obstacle(bearing, 0.3);
            map.obstacle(-bearing, 0.3);
        }
        assertEquals(0, map.bestTurn(), 1e-9, "3 m ahead: 2.4 m of new floor beyond the known 60 cm");
        map.horizon(0.6);
        assertEquals(180, Math.abs(map.bestTurn()), 1e-9, "within 60 cm only the floor behind is new");
        assertThrows(IllegalArgumentException.class, () -> map.horizon(0.05));
    }

    /** Straight at {@code speed} from {@code fromMs} to {@code toMs}, a wheel reading every 40 ms as the middleware gets them. */
    private void drive(long fromMs, long toMs, double speed) {
        for (long t = fromMs; t <= toMs; t += 40) {
            map.wheels(t, speed, speed);
        }
    }

    @Test
    void aWheelGeometryMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new ExplorationMap(0, 0.09));
        assertThrows(IllegalArgumentException.class, () -> new ExplorationMap(0.001, -1));
    }
}
