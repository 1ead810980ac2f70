package jacabot.sim.engine;

import org.dyn4j.collision.CollisionItem;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.world.WorldCollisionData;

/**
 * A contact pair's penetration that also remembers the pair's clearance, so that the narrow phase
 * ({@link BoundedGjk}) need not measure two shapes again while they have moved too little to touch
 * ({@link RememberedClearance}). dyn4j hands the narrow phase the penetration of the pair's collision
 * data, kept from step to step; the world makes its collision data with this penetration
 * ({@link Dyn4jWorld#createCollisionData}). Its normal and depth are dyn4j's as before.
 */
final class ClearancePenetration extends Penetration {
    final RememberedClearance clearance = new RememberedClearance();
    /** The pair's bodies, in the narrow phase's order. */
    final TrackedBody body1, body2;

    ClearancePenetration(TrackedBody body1, TrackedBody body2) {
        this.body1 = body1;
        this.body2 = body2;
    }

    /** dyn4j's collision data, with a {@link ClearancePenetration} in place of its own penetration. */
    static final class Data extends WorldCollisionData<Body> {
        private final ClearancePenetration penetration;

        Data(CollisionPair<CollisionItem<Body, BodyFixture>> pair) {
            super(pair);
            penetration = new ClearancePenetration((TrackedBody) getBody1(), (TrackedBody) getBody2());
        }

        @Override
        public Penetration getPenetration() {
            return penetration;
        }

        /** dyn4j's reset but for its own penetration, which nothing reads here ({@link #getPenetration}). */
        @Override
        public void reset() {
            setBroadphaseCollision(false);
            setNarrowphaseCollision(false);
            setManifoldCollision(false);
            setContactConstraintCollision(false);
            penetration.clear();
            getManifold().clear();
        }
    }
}
