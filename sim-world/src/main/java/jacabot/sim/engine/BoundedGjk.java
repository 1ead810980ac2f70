package jacabot.sim.engine;

import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.NarrowphaseDetector;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;

/**
 * dyn4j's narrow phase (GJK, its default) with a cheap test in front: two shapes whose bounding
 * circles or edge lines keep them apart ({@link BoundedAdvancement#clearance}) do not touch, and GJK
 * says so too. dyn4j sends it every pair its broad phase keeps, boxes grown by 0.2 m, so most pairs
 * it tests at each physics step are centimetres apart.
 *
 * <p>Why the answers are the same: GJK answers {@code false} for shapes a positive distance apart;
 * the test answers {@code false} only past {@link #SLACK}, a micrometre, far above the rounding of
 * either computation, and leaves the penetration untouched, as the world reads it only after
 * {@code true}. Every other pair goes to GJK unchanged ({@code BoundedGjkTest}). A pair whose
 * penetration remembers its clearance ({@link ClearancePenetration}) is not measured again while the
 * remembered bound on its distance stays above the test's threshold by {@link RememberedClearance#SLACK}.
 */
final class BoundedGjk implements NarrowphaseDetector {
    /** How far apart the test must find two shapes before it answers for GJK, in metres. */
    static final double SLACK = 1e-6;

    private final Gjk gjk = new Gjk();

    @Override
    public boolean detect(Convex convex1, Transform transform1, Convex convex2, Transform transform2, Penetration penetration) {
        if (penetration instanceof ClearancePenetration p && transform1 == p.body1.getTransform() && transform2 == p.body2.getTransform()) {
            RememberedClearance c = p.clearance;
            // the test below's answer: the full clearance is its terms' largest
            return !c.exceeds(p.body1, p.body2, SLACK)
                    && !(c.measure(p.body1, convex1, transform1, p.body2, convex2, transform2) > SLACK)
                    && gjk.detect(convex1, transform1, convex2, transform2, penetration);
        }
        return !apart(convex1, transform1, convex2, transform2) && gjk.detect(convex1, transform1, convex2, transform2, penetration);
    }

    @Override
    public boolean detect(Convex convex1, Transform transform1, Convex convex2, Transform transform2) {
        return !apart(convex1, transform1, convex2, transform2) && gjk.detect(convex1, transform1, convex2, transform2);
    }

    private static boolean apart(Convex convex1, Transform transform1, Convex convex2, Transform transform2) {
        return BoundedAdvancement.clearanceExceeds(convex1, transform1, convex2, transform2, 0, SLACK);
    }
}
