package jacabot.sim.engine;

import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.ConstraintGraphNode;

/**
 * A dyn4j body that holds its own entry in each of the world's two broad phases
 * ({@link StillFixedBodies}), so that the questions dyn4j asks about a body at every physics step
 * for every pair it keeps (is it still in the tree, did it move in this step) are a field read, not
 * a hash lookup of the body and its fixture; likewise the island solve's question whether the body is on an
 * island yet ({@link Islands}). Every body of a {@link Physics} world is one.
 */
final class TrackedBody extends Body {
    StillFixedBodies.Entry<?> contactEntry;
    StillFixedBodies.Entry<?> continuousEntry;
    /** {@link Islands}' marks: the last physics step the body was on an island as a moving body, and the last island it joined fixed. */
    long islandStep, staticIsland;
    /**
     * The body's node in its world's constraint graph, set when the body joins the world (dyn4j makes
     * the node then, and anew if it joins again), so that the island walk reads a field where it looked
     * the body up in the graph's hash map ({@link Dyn4jWorld#addBody}).
     */
    ConstraintGraphNode<Body> graphNode;

    /**
     * A bound on how far any point of the body has moved, in metres, over the transforms counted so
     * far ({@link #countMotion}): between two of them no point moved farther than the odometer's
     * advance (the triangle inequality over the ones between). Read by {@link RememberedClearance}.
     */
    double odometer;
    private double countedX, countedY, countedCos = 1, countedSin;
    /** The farthest a point of the body's fixtures lies from its origin: a fixture's centre's distance plus its radius. */
    private double extent;
    /**
     * Whether the body has infinite mass: nothing but a teleport moves it ({@link StillFixedBodies}),
     * so its motion is counted there ({@link #teleported()}) and the step's counts pass it by.
     */
    boolean fixed;

    /** Called when the body joins a world, its fixtures and mass set: keeps its extent and whether it is fixed, and counts its motion. */
    void joined() {
        extent = 0;
        for (int i = 0, n = getFixtureCount(); i < n; i++) {
            Convex c = getFixture(i).getShape();
            Vector2 centre = c.getCenter();
            extent = Math.max(extent, Math.sqrt(centre.x * centre.x + centre.y * centre.y) + c.getRadius());
        }
        fixed = getMass().isInfinite();
        countMotion();
    }

    /**
     * Advances the odometer by a bound on how far any point moved from the transform last counted to
     * the body's transform now: a translation by d and a rotation changed by {@code R - R0} move a
     * point at {@code p} from the origin by at most {@code |d| + |p| ‖R - R0‖}, {@code ‖R - R0‖} being
     * the length of the cosine's and sine's change, {@code |p|} at most the body's {@link #extent}.
     */
    void countMotion() {
        Transform t = getTransform();
        double x = t.getTranslationX(), y = t.getTranslationY(), cos = t.getCost(), sin = t.getSint();
        if (x == countedX && y == countedY && cos == countedCos && sin == countedSin) {
            return;
        }
        double dx = x - countedX, dy = y - countedY, dc = cos - countedCos, ds = sin - countedSin;
        odometer += Math.sqrt(dx * dx + dy * dy) + extent * Math.sqrt(dc * dc + ds * ds);
        countedX = x;
        countedY = y;
        countedCos = cos;
        countedSin = sin;
    }

    /**
     * Tells the broad phases that the body was moved from outside dyn4j's step (a teleport): a fixed
     * body is measured again only then ({@link StillFixedBodies}), and its motion counted only then.
     */
    void teleported() {
        if (fixed) {
            countMotion();
        }
        if (contactEntry != null) {
            contactEntry.watch();
        }
        if (continuousEntry != null) {
            continuousEntry.watch();
        }
    }
}
