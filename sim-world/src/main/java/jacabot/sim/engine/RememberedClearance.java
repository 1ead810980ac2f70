package jacabot.sim.engine;

import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;

/**
 * The clearance of two placed shapes ({@link BoundedAdvancement#clearance}, a lower bound of their
 * distance) as last measured, and a lower bound of their distance since: a shape whose transform's
 * translation moved by {@code dt} and whose rotation changed by {@code R - R0} moves none of its points
 * farther than {@code |dt| + |p| ‖R - R0‖}, with {@code |p|} at most its centre's distance from the
 * body's origin plus its radius; so the distance now is at least the clearance measured less both
 * shapes' such bounds. Kept by a pair that dyn4j asks about at every physics step, most of whose
 * pairs are centimetres apart and move a millimetre a step ({@link ClearancePair},
 * {@link ClearancePenetration}). Not thread-safe: a world is stepped by one thread.
 */
final class RememberedClearance {
    /**
     * Margin on the remembered bound, in metres: far above its rounding and GJK's tolerances, which is
     * what lets the bound stand where the test it replaces had its own slack.
     */
    static final double SLACK = 1e-5;

    private Convex a, b; // null: nothing measured
    private double gap;
    private double ax, ay, aCos, aSin, bx, by, bCos, bSin;
    private long measured, remembered;

    /**
     * {@return whether the distance of the shapes, so placed, is sure to exceed {@code threshold}
     * plus {@link #SLACK} by what was last measured of them (false when they were not measured in this order)}
     */
    boolean exceeds(Convex a, Transform ta, Convex b, Transform tb, double threshold) {
        if (a != this.a || b != this.b) {
            return false;
        }
        double bound = gap - moved(a, ta, ax, ay, aCos, aSin) - moved(b, tb, bx, by, bCos, bSin);
        if (bound - SLACK > threshold) {
            remembered++;
            return true;
        }
        return false;
    }

    /** {@return the shapes' clearance, all its terms worked out, now remembered} */
    double measure(Convex a, Transform ta, Convex b, Transform tb) {
        measured++;
        this.a = a;
        this.b = b;
        gap = BoundedAdvancement.clearance(a, ta, b, tb);
        ax = ta.getTranslationX();
        ay = ta.getTranslationY();
        aCos = ta.getCost();
        aSin = ta.getSint();
        bx = tb.getTranslationX();
        by = tb.getTranslationY();
        bCos = tb.getCost();
        bSin = tb.getSint();
        return gap;
    }

    /** {@return a bound on how far any point of the shape moved from the remembered transform to {@code t}} */
    private static double moved(Convex shape, Transform t, double x0, double y0, double cos0, double sin0) {
        double dx = t.getTranslationX() - x0, dy = t.getTranslationY() - y0;
        double dc = t.getCost() - cos0, ds = t.getSint() - sin0;
        Vector2 c = shape.getCenter();
        double extent = Math.sqrt(c.x * c.x + c.y * c.y) + shape.getRadius();
        return Math.sqrt(dx * dx + dy * dy) + extent * Math.sqrt(dc * dc + ds * ds);
    }

    /** {@return how many times the shapes were measured, and how many the remembered bound answered} */
    long[] counts() {
        return new long[] {measured, remembered};
    }
}
