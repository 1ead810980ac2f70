package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class MouthShapeTest {
    /** The tried parameters: the weaker reading 40 or more, steady within 10, the other up by 30, over 6 pairs and 1.5 cm. */
    private static MouthShape shape() {
        return new MouthShape(40, 10, 30, 6, 0.015);
    }

    /** Feeds pairs driving 4 mm a pair along z; {@return the last answer} */
    private static boolean feed(MouthShape shape, double[] left, double[] right, double step) {
        boolean last = false;
        for (int k = 0; k < left.length; k++) {
            last = shape.read(left[k], right[k], 0, k * step);
        }
        return last;
    }

    @Test
    void aSteadyWeakSideAndAClimbingJambAreAMouthOnEitherSide() {
        // wide tuning world 130 seed 2, 9.5-10 s: the left ray goes into the passage and settles
        double[] settling = {44, 48, 52, 56, 60, 64, 68, 73, 74, 75, 75, 76, 76};
        assertTrue(feed(shape(), settling, CLIMBING, 0.004));
        assertTrue(feed(shape(), CLIMBING, settling, 0.004), "mirrored");
    }

    @Test
    void aBoxMetOffCentreAPlainWallAWallBesideATurnOnTheSpotAndAShortHistoryAreNot() {
        double[] settling = {44, 48, 52, 56, 60, 64, 68, 73, 74, 75, 75, 76, 76};
        assertFalse(feed(shape(), new double[13], CLIMBING, 0.004), "nothing on the weak side: a box");
        double[] both = {40, 50, 60, 70, 80, 95, 110, 125, 140, 155, 170, 185, 200};
        assertFalse(feed(shape(), both, CLIMBING, 0.004), "both climb: a wall");
        double[] flatStrong = {200, 200, 201, 200, 202, 201, 203, 200, 201, 200, 202, 201, 203};
        assertFalse(feed(shape(), settling, flatStrong, 0.004), "the strong side does not climb");
        double[] beside = {75, 75, 76, 75, 75, 74, 75, 76, 75, 75, 75, 76, 75};
        assertFalse(feed(shape(), beside, CLIMBING, 0.004), "steady for long: a wall beside the robot");
        assertFalse(feed(shape(), settling, CLIMBING, 0), "turning on the spot");
        assertFalse(feed(shape(), new double[] {68, 76, 76}, new double[] {164, 200, 232}, 0.004), "fewer pairs than two windows");
    }

    private static final double[] CLIMBING = {106, 115, 124, 133, 144, 153, 164, 175, 186, 197, 211, 224, 232};
}
