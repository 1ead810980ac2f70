package jacabot.sim.engine;

import org.dyn4j.collision.continuous.ConservativeAdvancement;
import org.dyn4j.collision.continuous.TimeOfImpact;
import org.dyn4j.collision.continuous.TimeOfImpactDetector;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Polygon;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;

/**
 * dyn4j's conservative advancement (its default time-of-impact detector), with a cheap test in
 * front: a pair that cannot close the gap between them within the interval gets no GJK distance.
 *
 * <p>Why the answers are the same: {@link ConservativeAdvancement} first advances by
 * {@code d / (rv·n + amax)}, with {@code d} the GJK distance, {@code rv} the relative motion and
 * {@code amax} its rotation bound, and answers {@code false} once the time passes {@code t2}.
 * Here {@code gap} is a lower bound of {@code d} (bounding circles and the polygons' edge lines) and
 * {@code |rv| + amax} an upper bound of the speed, so when {@code gap} exceeds what that speed
 * covers by {@code t2}, its first advance passes {@code t2} and its answer is {@code false}, which
 * is ours. Every other pair goes to it unchanged. {@code BoundedAdvancementTest} compares the two
 * on random pairs. Most of the world's pairs (the continuous broad phase pairs any bodies whose
 * grown boxes touch) are centimetres apart and move a millimetre per physics step.
 */
final class BoundedAdvancement implements TimeOfImpactDetector {
    /** Slack on both sides of the test, far above the rounding of either computation. */
    private static final double RELATIVE_SLACK = 1e-6;
    static final double ABSOLUTE_SLACK = 1e-9;

    private final ConservativeAdvancement exact = new ConservativeAdvancement();
    private long skipped;

    @Override
    public boolean getTimeOfImpact(Convex convex1, Transform transform1, Vector2 dp1, double da1,
            Convex convex2, Transform transform2, Vector2 dp2, double da2, TimeOfImpact toi) {
        return getTimeOfImpact(convex1, transform1, dp1, da1, convex2, transform2, dp2, da2, 0.0, 1.0, toi);
    }

    @Override
    public boolean getTimeOfImpact(Convex convex1, Transform transform1, Vector2 dp1, double da1,
            Convex convex2, Transform transform2, Vector2 dp2, double da2, double t1, double t2, TimeOfImpact toi) {
        if (cannotMeet(convex1, transform1, dp1.x, dp1.y, da1, convex2, transform2, dp2.x, dp2.y, da2, t1, t2)) {
            skipped++;
            return false;
        }
        return exact.getTimeOfImpact(convex1, transform1, dp1, da1, convex2, transform2, dp2, da2, t1, t2, toi);
    }

    /**
     * {@return whether the test above answers {@code false} for the pair: then so does
     * {@link #getTimeOfImpact}, for this interval and every interval inside it}
     */
    static boolean cannotMeet(Convex convex1, Transform transform1, double dp1x, double dp1y, double da1,
            Convex convex2, Transform transform2, double dp2x, double dp2y, double da2, double t1, double t2) {
        double reach = reach(convex1, dp1x, dp1y, da1, convex2, dp2x, dp2y, da2, t1, t2);
        return clearanceExceeds(convex1, transform1, convex2, transform2, ABSOLUTE_SLACK, reach);
    }

    /**
     * {@return how far the two shapes may close on each other within the interval, with slack: the
     * threshold {@link #cannotMeet} tests the clearance less {@link #ABSOLUTE_SLACK} against}
     */
    static double reach(Convex convex1, double dp1x, double dp1y, double da1,
            Convex convex2, double dp2x, double dp2y, double da2, double t1, double t2) {
        double rx = dp1x - dp2x;
        double ry = dp1y - dp2y;
        double speed = Math.sqrt(rx * rx + ry * ry) + (convex1.getRadius() * Math.abs(da1) + convex2.getRadius() * Math.abs(da2));
        return ((t2 - t1) * (1 + RELATIVE_SLACK) + ABSOLUTE_SLACK) * speed * (1 + RELATIVE_SLACK);
    }

    /** {@return how many pairs the test answered without a GJK distance} */
    long skipped() {
        return skipped;
    }

    /** {@return a lower bound of the distance between the two placed shapes; negative when it may be 0} */
    static double clearance(Convex a, Transform ta, Convex b, Transform tb) {
        return clearance(a, ta, b, tb, 0, Double.POSITIVE_INFINITY);
    }

    /**
     * {@return {@code clearance(a, ta, b, tb) - slack > threshold}, to the bit} The clearance is the
     * largest of its terms (the circles' gap, then each edge's), and subtracting a number keeps their
     * order, so it passes exactly when one of them does: the terms are worked out only until one
     * passes, and most pairs pass on the circles' gap or the first edges.
     */
    static boolean clearanceExceeds(Convex a, Transform ta, Convex b, Transform tb, double slack, double threshold) {
        return clearance(a, ta, b, tb, slack, threshold) - slack > threshold;
    }

    /** The clearance, or as soon as a term less {@code slack} exceeds {@code threshold}, a value that does too. */
    private static double clearance(Convex a, Transform ta, Convex b, Transform tb, double slack, double threshold) {
        Vector2 ca = a.getCenter(), cb = b.getCenter();
        double ax = ta.getTransformedX(ca), ay = ta.getTransformedY(ca);
        double bx = tb.getTransformedX(cb), by = tb.getTransformedY(cb);
        double dx = ax - bx, dy = ay - by;
        double gap = Math.sqrt(dx * dx + dy * dy) - a.getRadius() - b.getRadius(); // not hypot: StrictMath, and slow
        if (gap - slack > threshold) {
            return gap;
        }
        if (a instanceof Polygon p) {
            gap = Math.max(gap, edgeGap(p, ta, bx, by, b.getRadius(), slack, threshold) - b.getRadius());
        }
        if (gap - slack <= threshold && b instanceof Polygon q) {
            gap = Math.max(gap, edgeGap(q, tb, ax, ay, a.getRadius(), slack, threshold) - a.getRadius());
        }
        return gap;
    }

    /**
     * The largest signed distance from the point (x, y) to the lines of the polygon's edges: the
     * polygon lies behind each line, so a shape of {@code radius} around the point is at least this
     * far minus its radius. The edges stop at the first whose distance, less radius and slack,
     * exceeds {@code threshold}.
     */
    private static double edgeGap(Polygon p, Transform t, double x, double y, double radius, double slack, double threshold) {
        // the point in the polygon's own frame: the inverse rotation of its offset
        double dx = x - t.getTranslationX(), dy = y - t.getTranslationY();
        double cos = t.getCost(), sin = t.getSint();
        double lx = cos * dx + sin * dy, ly = -sin * dx + cos * dy;
        Vector2[] vertices = p.getVertices();
        Vector2[] normals = p.getNormals();
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < vertices.length; i++) {
            Vector2 v = vertices[i], n = normals[i];
            double d = n.x * (lx - v.x) + n.y * (ly - v.y);
            best = Math.max(best, d);
            if (d - radius - slack > threshold) {
                break;
            }
        }
        return best;
    }
}
