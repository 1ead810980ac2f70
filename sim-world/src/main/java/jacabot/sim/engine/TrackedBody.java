package jacabot.sim.engine;

import org.dyn4j.dynamics.Body;
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
     * Tells the broad phases that the body was moved from outside dyn4j's step (a teleport): a fixed
     * body is measured again only then ({@link StillFixedBodies}).
     */
    void teleported() {
        if (contactEntry != null) {
            contactEntry.watch();
        }
        if (continuousEntry != null) {
            continuousEntry.watch();
        }
    }
}
