package jacabot.sim.engine;

import org.dyn4j.collision.CollisionItem;
import org.dyn4j.collision.broadphase.BroadphaseDetector;
import org.dyn4j.collision.broadphase.CollisionItemAABBProducer;
import org.dyn4j.collision.broadphase.CollisionItemBroadphaseDetector;
import org.dyn4j.collision.broadphase.CollisionItemBroadphaseDetectorAdapter;
import org.dyn4j.collision.broadphase.DynamicAABBTree;
import org.dyn4j.collision.broadphase.StaticValueAABBExpansionMethod;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.world.BroadphaseCollisionDataFilter;
import org.dyn4j.world.PhysicsBodySweptAABBProducer;
import org.dyn4j.world.World;

/**
 * dyn4j's two broad phases and its pair filter as a {@link World} builds them (the same trees, AABB
 * producers and 0.2 m expansion), less the pairs dyn4j drops at every step.
 *
 * <p>dyn4j keeps every pair whose grown boxes once overlapped in a list it walks at every physics
 * step (hash lookups per pair), and only then drops the pairs that can never collide. In an arena
 * that is mostly walls and fixed boxes most of those pairs are two fixed bodies. Here the trees do
 * not pair them at all:
 * <ul>
 * <li>the contact broad phase drops a pair of two fixed bodies, which dyn4j's pair filter
 * ({@code PhysicsBodyBroadphaseCollisionDataFilter}) refuses anyway: neither is dynamic and
 * neither fixture is a sensor (only carried cylinders become sensors, and they are dynamic);</li>
 * <li>the continuous collision broad phase keeps only a fixed body with a moving one: its time of
 * impact step skips two fixed bodies, and two dynamic bodies unless one is a bullet (none is);</li>
 * <li>the pair filter asks for the joints' consent only when the world has joints (it has none);</li>
 * <li>a fixed body that has not moved is not measured again at every step, and the trees' questions
 * about one body are answered from the body ({@link StillFixedBodies}, {@link TrackedBody});</li>
 * <li>a pair kept apart by its bounding circles or edge lines gets no GJK test ({@link BoundedGjk}).</li>
 * </ul>
 * The pairs left are those dyn4j keeps, found in the same order, so contacts are solved in the same
 * order and the trajectories are the same to the bit ({@code BroadPhasesTest}). That holds because a
 * body's mass type is set before it joins the world and never changes: a fixed body stays fixed.
 */
final class BroadPhases {
    /** dyn4j's own growth of every box in its broad phases, in metres. */
    private static final double EXPANSION = 0.2;

    private BroadPhases() {
    }

    /** Gives an empty world the broad phases and the pair filter above. */
    static void install(World<Body> world) {
        if (world.getBodyCount() > 0) {
            throw new IllegalStateException("the broad phases are set before the first body");
        }
        BroadphaseDetector<CollisionItem<Body, BodyFixture>> contacts = new StillFixedBodies<>(new DynamicAABBTree<>(
                (a, b) -> a != b && a.getBody() != b.getBody() && !(fixed(a.getBody()) && fixed(b.getBody())),
                new CollisionItemAABBProducer<>(), new StaticValueAABBExpansionMethod<>(EXPANSION),
                World.DEFAULT_INITIAL_BODY_CAPACITY), CollisionItem::getBody, new StillFixedBodies.Slot<>() {
                    @Override
                    @SuppressWarnings("unchecked")
                    public StillFixedBodies.Entry<CollisionItem<Body, BodyFixture>> get(CollisionItem<Body, BodyFixture> item) {
                        return (StillFixedBodies.Entry<CollisionItem<Body, BodyFixture>>) tracked(item.getBody()).contactEntry;
                    }

                    @Override
                    public void set(CollisionItem<Body, BodyFixture> item, StillFixedBodies.Entry<CollisionItem<Body, BodyFixture>> entry) {
                        tracked(item.getBody()).contactEntry = entry;
                    }
                });
        CollisionItemBroadphaseDetector<Body, BodyFixture> adapter = new CollisionItemBroadphaseDetectorAdapter<>(contacts);
        adapter.setUpdateTrackingEnabled(true);
        world.setBroadphaseDetector(adapter);

        BroadphaseDetector<Body> continuous = new StillFixedBodies<>(new DynamicAABBTree<>(
                (a, b) -> a != b && fixed(a) != fixed(b),
                new PhysicsBodySweptAABBProducer<>(), new StaticValueAABBExpansionMethod<>(EXPANSION),
                World.DEFAULT_INITIAL_BODY_CAPACITY), body -> body, new StillFixedBodies.Slot<>() {
                    @Override
                    @SuppressWarnings("unchecked")
                    public StillFixedBodies.Entry<Body> get(Body body) {
                        return (StillFixedBodies.Entry<Body>) tracked(body).continuousEntry;
                    }

                    @Override
                    public void set(Body body, StillFixedBodies.Entry<Body> entry) {
                        tracked(body).continuousEntry = entry;
                    }
                });
        continuous.setUpdateTrackingEnabled(true);
        world.setContinuousCollisionDetectionBroadphaseDetector(continuous);

        world.setBroadphaseCollisionDataFilter(new PairFilter(world));
        world.setNarrowphaseDetector(new BoundedGjk());
    }

    private static TrackedBody tracked(Body body) {
        if (body instanceof TrackedBody t) {
            return t;
        }
        throw new IllegalArgumentException("a body of this world is a TrackedBody, not a " + body.getClass().getSimpleName());
    }

    /** {@return whether the body has infinite mass: a wall or a fixed box} */
    static boolean fixed(Body body) {
        return body.getMass().isInfinite();
    }

    /** dyn4j's pair filter for a physics world, which asks the joints only when there are some. */
    private record PairFilter(World<Body> world) implements BroadphaseCollisionDataFilter<Body, BodyFixture> {
        @Override
        public boolean isAllowed(Body body1, BodyFixture fixture1, Body body2, BodyFixture fixture2) {
            if (!body1.isEnabled() || !body2.isEnabled() || !fixture1.getFilter().isAllowed(fixture2.getFilter())) {
                return false;
            }
            if (!body1.isDynamic() && !body2.isDynamic() && !fixture1.isSensor() && !fixture2.isSensor()) {
                return false;
            }
            return world.getJointCount() == 0 || world.isJointCollisionAllowed(body1, body2);
        }
    }
}
