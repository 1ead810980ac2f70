package jacabot.sim.engine;

import java.util.ArrayDeque;
import java.util.List;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.Settings;
import org.dyn4j.dynamics.TimeStep;
import org.dyn4j.dynamics.contact.ContactConstraint;
import org.dyn4j.dynamics.contact.ContactConstraintSolver;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.ConstraintGraph;
import org.dyn4j.world.ConstraintGraphNode;
import org.dyn4j.world.Island;

/**
 * dyn4j's island solve ({@code ConstraintGraph.solve}: a depth-first walk of the bodies and their
 * contact constraints, each island handed to dyn4j's {@link Island} as it is found) with marks on
 * the bodies ({@link TrackedBody}) where dyn4j keeps two hash sets, filled and cleared at every
 * physics step (its graph walk was 10 % of the world's samples, half of it the sets).
 *
 * <p>Why the islands are dyn4j's, in its order, with their bodies and constraints in its order:
 * the seeds are the world's bodies in the order they joined it, the order of dyn4j's graph (both
 * append a body when it joins and drop it when it leaves); a body is on an island in this step when
 * its mark is this step's, a fixed body on the current island when its other mark is this island's;
 * and a contact constraint is already on the island exactly when the body at its other end is: a
 * constraint joins an island while one of its two bodies is walked as a moving body, and a body is
 * walked once. dyn4j's own walk runs instead when the world has joints. {@code BroadPhasesTest} compares every body at every step with dyn4j's world
 * as it comes; {@code IslandsTest} with dyn4j's walk.
 *
 * <p>A body's node in the graph is the one it keeps ({@link TrackedBody#graphNode}), where dyn4j looks
 * it up in the graph's map at every visit (a sixth of the walk's samples).
 */
final class Islands {
    private final Island<Body> island = new Island<>();
    private final ArrayDeque<ConstraintGraphNode<Body>> stack = new ArrayDeque<>();
    /** This step's mark, and the current island's. */
    private long step, current;

    /**
     * Solves every island, as {@code graph.solve(solver, gravity, timeStep, settings)} does.
     * Every body is a {@link TrackedBody} ({@link Dyn4jWorld#addBody} takes no other).
     * {@return false, having solved nothing, when dyn4j's own walk must run: the world has joints}
     */
    boolean solve(List<Body> bodies, boolean joints, ConstraintGraph<Body> graph, ContactConstraintSolver<Body> solver,
                  Vector2 gravity, TimeStep timeStep, Settings settings) {
        if (joints) {
            return false;
        }
        step++;
        for (int i = 0, n = bodies.size(); i < n; i++) {
            TrackedBody seed = (TrackedBody) bodies.get(i);
            if (seed.islandStep == step || seed.isAtRest() || !seed.isEnabled() || seed.isStatic()) {
                continue;
            }
            current++;
            island.clear();
            stack.clear();
            stack.push(seed.graphNode);
            while (!stack.isEmpty()) {
                ConstraintGraphNode<Body> node = stack.pop();
                TrackedBody body = (TrackedBody) node.getBody();
                if (walked(body)) {
                    continue;
                }
                island.add(body);
                body.setAtRest(false);
                if (body.isStatic()) {
                    body.staticIsland = current; // an island spans one fixed body at most once, not beyond it
                    continue;
                }
                body.islandStep = step;
                List<ContactConstraint<Body>> contacts = node.getContactConstraints();
                for (int j = 0, m = contacts.size(); j < m; j++) {
                    ContactConstraint<Body> c = contacts.get(j);
                    if (!c.isEnabled() || c.isSensor()) {
                        continue;
                    }
                    TrackedBody other = (TrackedBody) c.getOtherBody(body);
                    if (other.islandStep == step) {
                        continue; // walked as a moving body, with this constraint: on the island already
                    }
                    island.add(c);
                    if (!walked(other)) {
                        stack.push(other.graphNode);
                    }
                }
            }
            island.solve(solver, gravity, timeStep, settings);
        }
        stack.clear();
        island.clear();
        return true;
    }

    /** {@return how many physics steps this walk solved} */
    long steps() {
        return step;
    }

    /** {@return whether the body is on an island of this step, or (fixed) on the current one} */
    private boolean walked(TrackedBody body) {
        return body.islandStep == step || body.staticIsland == current;
    }
}
