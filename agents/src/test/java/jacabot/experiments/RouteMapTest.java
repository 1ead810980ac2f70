package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

class RouteMapTest {
    /** A 2 m square arena, the Khepera's clearance, obstacles remembered for a minute. */
    private final RouteMap map = new RouteMap(2, 2, 0.04, 60_000);

    /** A wall seen along x = 0 from z = -1 to 1, but for a doorway from {@code from} to {@code to}. */
    private void wallWithDoorway(double from, double to, long nowMs) {
        for (double z = -1; z <= 1; z += 0.01) {
            if (z < from || z > to) {
                map.obstacle(0.001, z, nowMs);
            }
        }
    }

    @Test
    void theStraightWayWhenNothingIsInIt() {
        assertArrayEquals(new double[] {0.8, 0.5}, map.waypoint(-0.8, -0.5, 0.8, 0.5, 0), 1e-9);
        assertTrue(map.lastRoute().isEmpty());
    }

    @Test
    void throughTheDoorwayOfAWallSeenAcrossTheArena() {
        wallWithDoorway(0.50, 0.65, 0);
        double[] w = map.waypoint(-0.6, -0.5, 0.6, -0.5, 1000);
        List<double[]> route = map.lastRoute();
        assertFalse(route.isEmpty());
        double[] crossing = route.stream().filter(p -> Math.abs(p[0]) < RouteMap.CELL).findFirst().orElseThrow();
        assertTrue(crossing[1] > 0.5 && crossing[1] < 0.65, "the route crosses the wall in the doorway, at z = " + crossing[1]);
        // the first point to head for is on the robot's side, towards the doorway
        assertTrue(w[0] < 0.0 + RouteMap.CELL && w[1] > -0.5, "heads for the doorway first: " + w[0] + ", " + w[1]);
        // and from the doorway on, the straight way to the target
        assertArrayEquals(new double[] {0.6, -0.5}, map.waypoint(0.06, 0.575, 0.6, -0.5, 2000), 1e-9);
    }

    @Test
    void theRoutesLengthGoesByTheDoorwayAndLeavesTheRobotsRoute() {
        assertEquals(Math.hypot(1.2, 1.0), map.routeLength(-0.6, -0.5, 0.6, 0.5, 0), 1e-9);
        wallWithDoorway(0.50, 0.65, 0);
        map.waypoint(-0.6, -0.5, 0.6, -0.5, 1000);
        List<double[]> robots = map.lastRoute();
        // from (-0.6, -0.5) to (0.6, -0.5) by the doorway at z 0.5-0.65: the two straight legs through it, and a grid path's bends
        double viaDoorway = 2 * Math.hypot(0.6, 1.075);
        double length = map.routeLength(-0.6, -0.5, 0.6, -0.5, 1000);
        assertTrue(length > viaDoorway - 0.05 && length < viaDoorway + 0.3, "by the doorway: " + length + " m");
        // from the doorway on, the straight way
        assertEquals(Math.hypot(0.54, 1.075), map.routeLength(0.06, 0.575, 0.6, -0.5, 1000), 1e-9);
        assertTrue(robots == map.lastRoute(), "the robot's own route stays the inspector's");
    }

    @Test
    void aBoxThatMovedIsForgottenWhereTheRobotStandsOrOnceItsMemoryIsOver() {
        for (double z = -0.05; z <= 0.05; z += 0.01) {
            map.obstacle(0, z, 0);
        }
        assertTrue(map.blocked(0, 0, 1000));
        double[] w = map.waypoint(-0.5, 0, 0.5, 0, 1000);
        assertTrue(Math.abs(w[1]) > 0.02, "round the box, not through it: " + w[1]);
        // the robot's centre stood where the box was: the box has moved
        map.standing(0, 0);
        assertFalse(map.blocked(0, 0, 1000));
        // the rest of it is forgotten a minute after it was last seen
        assertTrue(map.blocked(0, 0.04, 59_999));
        assertArrayEquals(new double[] {0.5, 0}, map.waypoint(-0.5, 0, 0.5, 0, 60_000), 1e-9);
        assertFalse(map.blocked(0, 0.04, 60_000));
    }

    @Test
    void noRouteKnownGivesTheTargetItself() {
        // the target enclosed by obstacles seen all round it
        for (double a = 0; a < 2 * Math.PI; a += 0.02) {
            map.obstacle(0.5 + 0.1 * Math.cos(a), 0.5 + 0.1 * Math.sin(a), 0);
        }
        assertArrayEquals(new double[] {0.5, 0.5}, map.waypoint(-0.5, -0.5, 0.5, 0.5, 100), 1e-9);
        assertTrue(map.lastRoute().isEmpty());
    }

    @Test
    void aWallWithoutADoorwaySeenIsGoneRoundAtItsUnseenEnd() {
        // only the part of the wall the robot has met: z from -0.6 to 0.3
        for (double z = -0.6; z <= 0.3; z += 0.01) {
            map.obstacle(0.001, z, 0);
        }
        map.waypoint(-0.4, 0, 0.4, 0, 100);
        double[] crossing = map.lastRoute().stream().filter(p -> Math.abs(p[0]) < RouteMap.CELL).findFirst().orElseThrow();
        assertTrue(crossing[1] > 0.3, "round the nearer unseen end, at z = " + crossing[1]);
    }

    /**
     * A wall along x = 0 seen from z = -1 to 0 but for a doorway at z -0.95..-0.8 the robot drove
     * through; beyond z = 0 the wall has not been seen. Floor never seen is free: the route goes round
     * the face's unseen end. With the guess on, the face is taken to go on, and the route takes the
     * doorway driven through.
     */
    @Test
    void aDoorwayDrivenThroughIsTakenBeforeTheUnseenEndOfAFaceGuessedToGoOn() {
        RouteMap guessing = new RouteMap(2, 2, 0.04, 60_000);
        guessing.guessWalls(1.0);
        for (RouteMap m : List.of(map, guessing)) {
            for (double z = -1; z <= 0; z += 0.01) {
                if (z < -0.95 || z > -0.8) {
                    m.obstacle(0.001, z, 0);
                }
            }
            for (double x = -0.1; x <= 0.1; x += 0.01) {
                m.standing(x, -0.875);
            }
            m.waypoint(-0.2, -0.75, 0.3, 0.3, 100);
        }
        double open = crossingOf(map.lastRoute()), guessed = crossingOf(guessing.lastRoute());
        assertTrue(open > 0, "without the guess, round the unseen end: z = " + open);
        assertTrue(guessed > -0.95 && guessed < -0.8, "with it, through the doorway driven through: z = " + guessed);
    }

    /**
     * A wall's face seen along x = 0 from z = -0.8 to 0, the robot beside it at (-0.06, -0.05), the target
     * across it, the guess on (1 m). The guess alone is crossed just past the seen end (the robot turned
     * into the wall's unseen part there at every plan and crept along it); made firm for 0.15 m, it is
     * crossed past the firm part; a side sensor that saw the floor open on the face's line, 5 cm past the
     * seen end, ends the guess: crossed there.
     */
    @Test
    void aFirmGuessIsCrossedPastItsFirmPartOrWhereTheFloorWasSeenOpen() {
        double[] crossings = new double[3];
        for (int variant = 0; variant < 3; variant++) {
            RouteMap m = new RouteMap(2, 2, 0.04, 60_000);
            m.guessWalls(1.0);
            if (variant > 0) {
                m.guessWallsFirm(0.15);
            }
            for (double z = -0.8; z <= 0; z += 0.01) {
                m.obstacle(0.001, z, 0);
            }
            if (variant == 2) {
                m.seenFree(-0.03, 0.05, 0.01, 0.05);
            }
            m.waypoint(-0.06, -0.05, 0.4, -0.2, 100);
            crossings[variant] = crossingOf(m.lastRoute());
        }
        assertTrue(crossings[0] < 0.1, "the guess alone, just past the seen end: z = " + crossings[0]);
        assertTrue(crossings[1] > 0.12, "firm, past its firm part: z = " + crossings[1]);
        assertTrue(crossings[2] < 0.1, "seen open, there: z = " + crossings[2]);
    }

    private static double crossingOf(List<double[]> route) {
        return route.stream().filter(p -> Math.abs(p[0]) < RouteMap.CELL).findFirst().orElseThrow()[1];
    }

    @Test
    void badArenasAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new RouteMap(0, 2, 0.04, 1000));
        assertThrows(IllegalArgumentException.class, () -> new RouteMap(2, 2, 0.04, 0));
        assertEquals(0.0, new RouteMap(1, 1, 0, 1).lastRoute().size());
    }

    /**
     * The map keeps its costs and its plan while no cell's blocking changes (and the plan while the
     * start and goal cells stay): every waypoint and route equals a fresh map's, fed the same
     * sightings and asked once, over a robot's random drive among boxes seen, forgotten and stood on.
     */
    @Test
    void aMapAskedAtEveryStepAnswersAsAFreshMapFedTheSame() {
        Random random = new Random(7);
        RouteMap kept = new RouteMap(2, 2, 0.04, 5_000);
        List<Consumer<RouteMap>> fed = new ArrayList<>();
        Consumer<Consumer<RouteMap>> feed = f -> {
            f.accept(kept);
            fed.add(f);
        };
        double x = -0.8, z = -0.8, tx = 0.8, tz = 0.7;
        int routes = 0;
        for (int step = 0; step < 600; step++) {
            long now = step * 40L;
            if (random.nextInt(10) == 0) { // a box's side seen: a row of cells
                double bx = random.nextDouble() * 1.6 - 0.8, bz = random.nextDouble() * 1.6 - 0.8;
                boolean alongX = random.nextBoolean();
                for (int k = 0; k < 12; k++) {
                    double ox = bx + (alongX ? k * 0.02 : 0), oz = bz + (alongX ? 0 : k * 0.02);
                    feed.accept(m -> m.obstacle(ox, oz, now));
                }
            }
            if (random.nextInt(40) == 0) {
                tx = random.nextDouble() * 1.8 - 0.9;
                tz = random.nextDouble() * 1.8 - 0.9;
            }
            double sx = x, sz = z;
            feed.accept(m -> m.standing(sx, sz));
            RouteMap fresh = new RouteMap(2, 2, 0.04, 5_000);
            fed.forEach(f -> f.accept(fresh));
            double[] expected = fresh.waypoint(x, z, tx, tz, now);
            double[] got = kept.waypoint(x, z, tx, tz, now);
            assertArrayEquals(expected, got, 0.0, "step " + step);
            assertEquals(fresh.lastRoute().size(), kept.lastRoute().size(), "step " + step);
            for (int k = 0; k < fresh.lastRoute().size(); k++) {
                assertArrayEquals(fresh.lastRoute().get(k), kept.lastRoute().get(k), 0.0);
            }
            routes += kept.lastRoute().isEmpty() ? 0 : 1;
            double d = Math.hypot(got[0] - x, got[1] - z), s = Math.min(0.03, d);
            if (d > 0 && step % 4 == 0) { // the robot stands still between moves, as the map changes
                x += (got[0] - x) / d * s + (random.nextDouble() - 0.5) * 0.004;
                z += (got[1] - z) / d * s + (random.nextDouble() - 0.5) * 0.004;
            }
        }
        assertTrue(routes > 100, "the drive went round boxes, not only straight: " + routes + " routes");
    }
}
