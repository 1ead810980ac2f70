package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.dyn4j.collision.broadphase.CollisionBodyAABBProducer;
import org.dyn4j.collision.broadphase.DynamicAABBTree;
import org.dyn4j.collision.broadphase.StaticValueAABBExpansionMethod;
import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.world.PhysicsBodySweptAABBProducer;
import org.junit.jupiter.api.Test;

/**
 * {@link StillFixedBodies} answers what dyn4j's tree answers (does it hold a body, was the body
 * updated since the last clearing, do two bodies' boxes overlap, each body's box), from each body's
 * entry, while bodies move a little or far, fixed bodies are teleported (and say so, as
 * {@code SimObject.place} does: a fixed body is compared again only then), bodies are removed and
 * added, and updates are cleared, in random order.
 */
class StillFixedBodiesTest {
    private static DynamicAABBTree<Body> tree() {
        return new DynamicAABBTree<>((a, b) -> a != b, new CollisionBodyAABBProducer<>(), new StaticValueAABBExpansionMethod<>(0.2), 16);
    }

    private static StillFixedBodies<Body> ours(DynamicAABBTree<Body> tree) {
        return new StillFixedBodies<>(tree, b -> b, new StillFixedBodies.Slot<>() {
            @Override
            @SuppressWarnings("unchecked")
            public StillFixedBodies.Entry<Body> get(Body body) {
                return (StillFixedBodies.Entry<Body>) ((TrackedBody) body).continuousEntry;
            }

            @Override
            public void set(Body body, StillFixedBodies.Entry<Body> entry) {
                ((TrackedBody) body).continuousEntry = entry;
            }
        });
    }

    /**
     * The continuous broad phase's swept boxes grow with a step's move and shrink after it: the tree
     * re-inserts an item whose box has become more than twice too large, which the shortcut past the
     * tree's lookup must see as the tree does.
     */
    @Test
    void sweptBoxesThatShrinkAreUpdatedAsDyn4jsTreeDoes() {
        Random rnd = new Random(11);
        DynamicAABBTree<Body> plain = swept();
        StillFixedBodies<Body> ours = ours(swept());
        List<Body> bodies = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            Body b = new TrackedBody();
            b.addFixture(i % 2 == 0 ? Geometry.createCircle(0.02) : Geometry.createRectangle(0.05, 0.08));
            b.setMass(MassType.NORMAL);
            b.translate(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1);
            b.getPreviousTransform().set(b.getTransform());
            bodies.add(b);
            plain.add(b);
            ours.add(b);
        }
        int reinserted = 0;
        for (int step = 0; step < 1_000; step++) {
            for (Body b : bodies) {
                b.getPreviousTransform().set(b.getTransform());
                double reach = rnd.nextDouble() < 0.05 ? 0.6 : 0.004; // now and then a fast step, then slow ones
                b.translate((rnd.nextDouble() - 0.5) * reach, (rnd.nextDouble() - 0.5) * reach);
            }
            plain.update();
            ours.update();
            for (Body b : bodies) {
                assertEquals(box(plain.getAABB(b)), box(ours.getAABB(b)), "step " + step);
                assertEquals(plain.isUpdated(b), ours.isUpdated(b), "step " + step);
                reinserted += plain.isUpdated(b) ? 1 : 0;
            }
            plain.clearUpdates();
            ours.clearUpdates();
        }
        assertTrue(reinserted > 500, reinserted + " re-insertions");
    }

    private static DynamicAABBTree<Body> swept() {
        DynamicAABBTree<Body> t = new DynamicAABBTree<>((a, b) -> a != b, new PhysicsBodySweptAABBProducer<>(),
                new StaticValueAABBExpansionMethod<>(0.2), 16);
        t.setUpdateTrackingEnabled(true);
        return t;
    }

    @Test
    void answersAsDyn4jsTreeDoes() {
        Random rnd = new Random(5);
        DynamicAABBTree<Body> plain = tree();
        StillFixedBodies<Body> ours = ours(tree());
        ours.setUpdateTrackingEnabled(true);
        plain.setUpdateTrackingEnabled(true);
        List<Body> bodies = new ArrayList<>(), removed = new ArrayList<>();
        for (int i = 0; i < 30; i++) {
            Body b = new TrackedBody();
            b.addFixture(i % 2 == 0 ? Geometry.createCircle(0.02) : Geometry.createRectangle(0.05, 0.08));
            b.setMass(i % 3 == 0 ? MassType.INFINITE : MassType.NORMAL);
            b.translate(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1);
            bodies.add(b);
            plain.add(b);
            ours.add(b);
        }
        int updated = 0, overlaps = 0;
        for (int step = 0; step < 2_000; step++) {
            for (Body b : bodies) {
                double r = rnd.nextDouble();
                if (!BroadPhases.fixed(b) && r < 0.5) {
                    b.translate((rnd.nextDouble() - 0.5) * 0.02, (rnd.nextDouble() - 0.5) * 0.02); // a step's move
                } else if (r < 0.52) {
                    b.getTransform().setTranslation(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1); // a teleport
                    ((TrackedBody) b).teleported(); // as SimObject.place says it
                }
                b.getPreviousTransform().set(b.getTransform());
            }
            int action = rnd.nextInt(20);
            if (action == 0 && bodies.size() > 5) {
                Body b = bodies.remove(rnd.nextInt(bodies.size()));
                assertEquals(plain.remove(b), ours.remove(b));
                removed.add(b);
            } else if (action == 1 && !removed.isEmpty()) {
                Body b = removed.remove(0);
                bodies.add(b);
                plain.add(b);
                ours.add(b);
            } else if (action == 2 && !bodies.isEmpty()) {
                Body b = bodies.get(rnd.nextInt(bodies.size()));
                plain.setUpdated(b);
                ours.setUpdated(b);
            }
            plain.update();
            ours.update();
            for (Body a : bodies) {
                assertEquals(plain.contains(a), ours.contains(a));
                assertEquals(plain.isUpdated(a), ours.isUpdated(a), "step " + step);
                assertEquals(box(plain.getAABB(a)), box(ours.getAABB(a)));
                updated += plain.isUpdated(a) ? 1 : 0;
                for (Body b : bodies) {
                    assertEquals(plain.detect(a, b), ours.detect(a, b));
                    overlaps += plain.detect(a, b) ? 1 : 0;
                }
            }
            for (Body a : removed) {
                assertEquals(plain.contains(a), ours.contains(a));
                assertEquals(plain.isUpdated(a), ours.isUpdated(a));
            }
            if (rnd.nextInt(3) > 0) {
                plain.clearUpdates();
                ours.clearUpdates();
            }
        }
        assertTrue(updated > 5_000 && overlaps > 5_000, updated + " updates, " + overlaps + " overlaps");
    }

    private static String box(AABB b) {
        return b.getMinX() + " " + b.getMinY() + " " + b.getMaxX() + " " + b.getMaxY();
    }
}
