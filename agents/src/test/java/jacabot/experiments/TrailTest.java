package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class TrailTest {
    private final Trail trail = new Trail();

    /** Drives the trail in a straight line from (x0, z0) to (x1, z1), a GPS reading every centimetre. */
    private void drive(double x0, double z0, double x1, double z1) {
        int n = (int) Math.ceil(Math.hypot(x1 - x0, z1 - z0) / 0.01);
        for (int k = 0; k <= n; k++) {
            trail.at(x0 + (x1 - x0) * k / n, z0 + (z1 - z0) * k / n);
        }
    }

    /** Follows the trail's waypoints from (x, z) to (tx, tz), 2 cm a step; {@return the metres driven} */
    private double follow(double x, double z, double tx, double tz, double maxFromWay, double[]... way) {
        double driven = 0;
        for (int step = 0; step < 1000 && Math.hypot(tx - x, tz - z) > 0.02; step++) {
            double[] w = trail.waypoint(x, z, tx, tz);
            assertNotNull(w, "the trail knows a way from " + x + ", " + z);
            double d = Math.hypot(w[0] - x, w[1] - z), s = Math.min(0.02, d);
            x += (w[0] - x) / d * s;
            z += (w[1] - z) / d * s;
            driven += s;
            assertTrue(fromWay(x, z, way) <= maxFromWay, "kept to the way driven: " + x + ", " + z);
        }
        assertTrue(Math.hypot(tx - x, tz - z) <= 0.02, "the target reached, at " + x + ", " + z);
        return driven;
    }

    /** The distance from (x, z) to the polyline {@code way}. */
    private static double fromWay(double x, double z, double[]... way) {
        double best = Double.POSITIVE_INFINITY;
        for (int i = 1; i < way.length; i++) {
            double[] a = way[i - 1], b = way[i];
            double dx = b[0] - a[0], dz = b[1] - a[1], len2 = dx * dx + dz * dz;
            double f = Math.max(0, Math.min(1, ((x - a[0]) * dx + (z - a[1]) * dz) / len2));
            best = Math.min(best, Math.hypot(x - a[0] - f * dx, z - a[1] - f * dz));
        }
        return best;
    }

    @Test
    void theWayBackGoesThroughTheDoorwayTheRobotCameBy() {
        // out: along a wall at x = 0 to its doorway at z = 0.6, through it, on to the charger at (0.6, -0.5)
        double[][] way = {{-0.6, -0.5}, {-0.06, 0.6}, {0.06, 0.6}, {0.6, -0.5}};
        for (int i = 1; i < way.length; i++) {
            drive(way[i - 1][0], way[i - 1][1], way[i][0], way[i][1]);
        }
        // from the charger, the point to head for is on the way back to the doorway, not straight across the wall
        double[] w = trail.waypoint(0.6, -0.5, -0.6, -0.5);
        assertTrue(w[0] < 0.6 && w[1] > -0.5, "towards the doorway: " + w[0] + ", " + w[1]);
        // and following the points leads back through the doorway, never more than 3 cm off the way out
        follow(0.6, -0.5, -0.6, -0.5, 0.03, way);
    }

    @Test
    void theLoopsOfTheWayOutAreCut() {
        // out: east 1 m, a loop (north, west, south back across the way), then on east
        double[][] way = {{-0.5, 0}, {0, 0}, {0, 0.4}, {-0.2, 0.4}, {-0.2, 0}, {0.5, 0}};
        for (int i = 1; i < way.length; i++) {
            drive(way[i - 1][0], way[i - 1][1], way[i][0], way[i][1]);
        }
        double driven = follow(0.5, 0, -0.5, 0, 0.03, way);
        assertTrue(driven < 1.1, "the way back is the straight metre, not the 2 m loop: " + driven);
    }

    @Test
    void theCornerOfAnObstacleGoneRoundIsNotCut() {
        // out round the corner of a box: north 0.3 m, then east 0.3 m
        drive(0, 0, 0, 0.3);
        drive(0, 0.3, 0.3, 0.3);
        // from 5 cm before the corner the point to head for is the corner, not a point past it
        double[] w = trail.waypoint(0, 0.25, 0.3, 0.3);
        assertTrue(w[0] < 0.03, "not past the corner: " + w[0] + ", " + w[1]);
        follow(0, 0, 0.3, 0.3, 0.026, new double[] {0, 0}, new double[] {0, 0.3}, new double[] {0.3, 0.3});
    }

    @Test
    void noWayWhereTheTrailHasNotBeen() {
        assertNull(trail.waypoint(0, 0, 1, 1), "an empty trail");
        drive(-0.5, 0, 0.5, 0);
        assertNull(trail.waypoint(0, 0, 0, 0.8), "the target far from the trail");
        assertNull(trail.waypoint(0, 0.8, 0.5, 0), "the robot far from the trail");
        // near the end of the way: the target itself
        assertArrayEquals(new double[] {0.5, 0}, trail.waypoint(0.42, 0, 0.5, 0), 1e-9);
    }

    /**
     * The trail keeps its last way to a goal point while it does not grow: every waypoint equals a
     * fresh trail's, given the same positions and asked once, over a random drive with targets
     * that change.
     */
    @Test
    void aTrailAskedAtEveryStepAnswersAsAFreshTrailOfTheSamePositions() {
        Random random = new Random(11);
        List<double[]> driven = new ArrayList<>();
        double x = 0, z = 0, heading = 0, tx = 0, tz = 0;
        int ways = 0;
        for (int step = 0; step < 800; step++) {
            heading += (random.nextDouble() - 0.5) * 0.6;
            x = Math.max(-0.9, Math.min(0.9, x + 0.01 * Math.cos(heading)));
            z = Math.max(-0.9, Math.min(0.9, z + 0.01 * Math.sin(heading)));
            trail.at(x, z);
            driven.add(new double[] {x, z});
            if (step % 60 == 0) {
                double[] back = driven.get(random.nextInt(driven.size()));
                tx = back[0] + 0.05;
                tz = back[1];
            }
            Trail fresh = new Trail();
            driven.forEach(p -> fresh.at(p[0], p[1]));
            double[] expected = fresh.waypoint(x, z, tx, tz), got = trail.waypoint(x, z, tx, tz);
            if (expected == null) {
                assertNull(got, "step " + step);
            } else {
                assertArrayEquals(expected, got, 0.0, "step " + step);
                ways++;
            }
        }
        assertTrue(ways > 200, "the trail gave ways: " + ways);
    }
}
