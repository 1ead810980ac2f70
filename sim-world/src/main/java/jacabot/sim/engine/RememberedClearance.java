package jacabot.sim.engine;

import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;

/**
 * The clearance of two bodies' shapes ({@link BoundedAdvancement#clearance}, a lower bound of their
 * distance) as last measured, and a lower bound of their distance since: no point of a body has
 * moved farther than its {@link TrackedBody#odometer} advanced, so the distance now is at least the
 * clearance measured less both odometers' advance since. Kept by a pair that dyn4j asks about at
 * every physics step, most of whose pairs are centimetres apart and move a millimetre a step
 * ({@link ClearancePair}, {@link ClearancePenetration}); the test then costs two subtractions where
 * the clearance's cost a square root and a polygon's edges. Not thread-safe: a world is stepped by one thread.
 */
final class RememberedClearance {
    /**
     * Margin on the remembered bound, in metres: far above its rounding and GJK's tolerances, which is
     * what lets the bound stand where the test it replaces had its own slack.
     */
    static final double SLACK = 1e-5;

    private TrackedBody a, b; // null: nothing measured
    private double gap, odometerA, odometerB;
    private long measured, remembered;

    /**
     * {@return whether the distance of the bodies' shapes, at the transforms their odometers last
     * counted, is sure to exceed {@code threshold} plus {@link #SLACK} by what was last measured of
     * them (false when they were not measured in this order)}
     */
    boolean exceeds(TrackedBody a, TrackedBody b, double threshold) {
        if (a != this.a || b != this.b) {
            return false;
        }
        if (gap - (a.odometer - odometerA) - (b.odometer - odometerB) - SLACK > threshold) {
            remembered++;
            return true;
        }
        return false;
    }

    /**
     * {@return the clearance of the shapes at these transforms, all its terms worked out, now
     * remembered} The transforms are the ones the bodies' odometers last counted.
     */
    double measure(TrackedBody a, Convex shapeA, Transform ta, TrackedBody b, Convex shapeB, Transform tb) {
        measured++;
        this.a = a;
        this.b = b;
        odometerA = a.odometer;
        odometerB = b.odometer;
        gap = BoundedAdvancement.clearance(shapeA, ta, shapeB, tb);
        return gap;
    }

    /** {@return how many times the shapes were measured, and how many the remembered bound answered} */
    long[] counts() {
        return new long[] {measured, remembered};
    }
}
