package jacabot.sim.device;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.robot.RobotModel;
import org.junit.jupiter.api.Test;

/**
 * Readings against hand-computed lookups. The Khepera (radius 0.0285 m) stands at the origin facing
 * north (+x); a white wall's south face is 2 cm ahead of its front sensor, at x = 0.0485.
 */
class DistanceSensorTest {
    static final double W = Math.exp(-0.25); // weight of the side rays at ±10° of a 20° aperture
    static final String WALL_AHEAD = "\"walls\": [{\"id\": \"w\", \"x\": 0.0985, \"z\": 0, \"size\": [0.1, 0.3], \"color\": \"%s\"}]";

    /** Khepera table by hand: piecewise linear through (0,1000) (0.015,480) (0.025,350) (0.04,200) (0.06,0). */
    static double khepera(double d) {
        if (d <= 0.015) return 1000 - d / 0.015 * 520;
        if (d <= 0.025) return 480 - (d - 0.015) / 0.010 * 130;
        if (d <= 0.040) return 350 - (d - 0.025) / 0.015 * 150;
        if (d <= 0.060) return 200 - (d - 0.040) / 0.020 * 200;
        return 0;
    }

    /** Three rays at -10°, 0°, +10° from a sensor whose axis makes angle a with the wall's normal, at normal distance n. */
    static double threeRays(double n, double a) {
        double c = khepera(n / Math.cos(Math.toRadians(a)));
        double l = khepera(n / Math.cos(Math.toRadians(a - 10)));
        double r = khepera(n / Math.cos(Math.toRadians(a + 10)));
        return (c + W * (l + r)) / (1 + 2 * W);
    }

    private static SimWorld wallAhead(String color) {
        return TestWorlds.khepera(0, 0, 0, String.format(WALL_AHEAD, color));
    }

    @Test
    void theTableInterpolatesLinearlyAndHoldsBeyondItsEnds() {
        LookupTable t = RobotModel.KHEPERA_TABLE;
        assertEquals(415.0, t.output(0.02), 1e-9);
        assertEquals(1000.0, t.output(-1), 1e-9);
        assertEquals(0.0, t.output(0.5), 1e-9);
        assertEquals(0.06, t.maxInput());
        assertEquals(0.01, t.noise(0.03), 1e-12);
    }

    @Test
    void theFrontSensorReadsTheWallTwoCentimetresAhead() {
        SimWorld w = wallAhead("white");
        DistanceSensor front = w.robot("k").getDistanceSensor("front");
        front.enable(40);
        w.step();
        double expected = (415 + 2 * W * khepera(0.02 / Math.cos(Math.toRadians(10)))) / (1 + 2 * W);
        assertEquals(expected, front.getValue(), 1e-6);
        assertEquals(threeRays(0.02, 0), front.getValue(), 1e-6);
        assertTrue(front.getValue() > 350 && front.getValue() < 480, "an obstacle, not yet very close");
    }

    @Test
    void theDiagonalSensorsSeeTheWallAtFortyFiveDegrees() {
        SimWorld w = wallAhead("white");
        DistanceSensor fl = w.robot("k").getDistanceSensor("front-left");
        DistanceSensor fr = w.robot("k").getDistanceSensor("front-right");
        fl.enable(40);
        fr.enable(40);
        w.step();
        double n = 0.0485 - 0.0285 * Math.cos(Math.toRadians(45));
        assertEquals(threeRays(n, 45), fl.getValue(), 1e-6);
        assertEquals(fl.getValue(), fr.getValue(), 1e-9);
    }

    @Test
    void theSideSensorsSeeNothingAndReadZero() {
        SimWorld w = wallAhead("white");
        DistanceSensor left = w.robot("k").getDistanceSensor("left");
        left.enable(40);
        w.step();
        assertEquals(0.0, left.getValue());
    }

    @Test
    void aDarkerSurfaceReflectsLessInfraRed() {
        SimWorld w = wallAhead("#808080");
        DistanceSensor front = w.robot("k").getDistanceSensor("front");
        front.enable(40);
        w.step();
        assertEquals(threeRays(0.02, 0) * 128 / 255.0, front.getValue(), 1e-6);
    }

    @Test
    void theFirstReadingComesOnlyAfterOnePeriod() {
        SimWorld w = wallAhead("white");
        DistanceSensor front = w.robot("k").getDistanceSensor("front");
        assertEquals(0, front.getSamplingPeriod());
        front.enable(40);
        assertEquals(40, front.getSamplingPeriod());
        assertTrue(Double.isNaN(front.getValue()));
        w.step(32);
        assertTrue(Double.isNaN(front.getValue()));
        w.step(8);
        assertEquals(threeRays(0.02, 0), front.getValue(), 1e-6);
        front.disable();
        assertEquals(0, front.getSamplingPeriod());
        assertTrue(Double.isNaN(front.getValue()));
    }

    @Test
    void readingsAreHeldBetweenSamples() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, String.format(WALL_AHEAD, "white"));
        DistanceSensor front = w.robot("k").getDistanceSensor("front");
        front.enable(80);
        w.step(80);
        double first = front.getValue();
        w.robot("k").setSpeeds(-100, -100); // backs away 2 mm per 40 ms
        w.step(40);
        assertEquals(first, front.getValue());
        w.step(40);
        assertTrue(front.getValue() < first);
    }

    @Test
    void myBotsSensorsSeeAWallAheadAtTwentyDegrees() {
        SimWorld w = TestWorlds.world("\"robots\": [{\"name\": \"m\", \"model\": \"mybot\"}],"
                + "\"walls\": [{\"x\": 0.2, \"z\": 0, \"size\": [0.1, 0.6]}]");
        DistanceSensor left = w.robot("m").getDistanceSensor("left");
        DistanceSensor right = w.robot("m").getDistanceSensor("right");
        left.enable(40);
        right.enable(40);
        w.step();
        double n = 0.15 - 0.045 * Math.cos(Math.toRadians(20)); // the wall's face at x = 0.15
        double wSide = Math.exp(-0.25);
        double expected = (myBot(n / Math.cos(Math.toRadians(20))) + wSide * (myBot(n / Math.cos(Math.toRadians(5)))
                + myBot(n / Math.cos(Math.toRadians(35))))) / (1 + 2 * wSide);
        assertEquals(expected, left.getValue(), 1e-6);
        assertEquals(left.getValue(), right.getValue(), 1e-9);
    }

    static double myBot(double d) {
        if (d <= 0.05) return 1000 - d / 0.05 * 520;
        if (d <= 0.08) return 480 - (d - 0.05) / 0.03 * 130;
        if (d <= 0.12) return 350 - (d - 0.08) / 0.04 * 150;
        if (d <= 0.20) return 200 - (d - 0.12) / 0.08 * 200;
        return 0;
    }

    @Test
    void noiseIsSeededGaussianAroundTheLookup() {
        String wall = String.format(WALL_AHEAD, "white");
        String members = "\"robots\": [{\"name\": \"k\", \"model\": \"khepera\"}], " + wall;
        SimWorld a = TestWorlds.world(members, true);
        SimWorld b = TestWorlds.world(members, true);
        DistanceSensor fa = a.robot("k").getDistanceSensor("front");
        DistanceSensor fb = b.robot("k").getDistanceSensor("front");
        fa.enable(8);
        fb.enable(8);
        double exact = threeRays(0.02, 0), sum = 0, sq = 0;
        int n = 2000;
        for (int i = 0; i < n; i++) {
            a.step(8);
            b.step(8);
            assertEquals(fa.getValue(), fb.getValue(), "same seed, same noise");
            sum += fa.getValue();
            sq += (fa.getValue() - exact) * (fa.getValue() - exact);
        }
        assertNotEquals(exact, fa.getValue());
        assertEquals(exact, sum / n, exact * 0.01 * 0.1); // mean within a tenth of a sigma
        assertEquals(exact * 0.01, Math.sqrt(sq / n), exact * 0.01 * 0.1); // sigma = 1 % of the value
    }
}
