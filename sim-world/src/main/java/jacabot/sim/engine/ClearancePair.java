package jacabot.sim.engine;

import org.dyn4j.collision.AbstractCollisionPair;
import org.dyn4j.collision.CollisionPair;
import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Vector2;

/**
 * A pair of the continuous broad phase that remembers the clearance it last measured
 * ({@link RememberedClearance}), so that the time-of-impact pass need not measure it again while both
 * bodies have moved too little to close it.
 *
 * <p>Why the answers are the same: when the remembered bound on the bodies' distance exceeds what
 * their relative speed covers in the step (the reach {@link BoundedAdvancement#cannotMeet} tests),
 * dyn4j's conservative advancement, whose first advance is its GJK distance (no less than the true
 * one) over that speed, passes the step's end and answers {@code false} for the pair: the answer of a
 * pair left out of the pass. Otherwise the pair is measured with the same test as before. Equal to
 * dyn4j's own pair of the same bodies (the set of pairs keeps whichever came first).
 */
final class ClearancePair implements CollisionPair<Body> {
    private final Body first, second;
    private final RememberedClearance clearance = new RememberedClearance();

    ClearancePair(Body first, Body second) {
        this.first = first;
        this.second = second;
    }

    @Override
    public Body getFirst() {
        return first;
    }

    @Override
    public Body getSecond() {
        return second;
    }

    @Override
    public CollisionPair<Body> copy() {
        return new ClearancePair(first, second);
    }

    @Override
    public boolean equals(Object o) {
        return AbstractCollisionPair.equals(this, o);
    }

    @Override
    public int hashCode() {
        return AbstractCollisionPair.getHashCode(first, second);
    }

    /**
     * {@return whether dyn4j's detector answers {@code false} for the bodies' fixtures in this step}
     * (one fixture each; the mover's and the other's previous transforms, which their odometers last
     * counted, and velocities, as dyn4j gives them)
     */
    boolean cannotMeet(TrackedBody mover, TrackedBody other, double dt) {
        Convex a = mover.getFixture(0).getShape(), b = other.getFixture(0).getShape();
        Vector2 v1 = mover.getLinearVelocity(), v2 = other.getLinearVelocity();
        double da1 = mover.getAngularVelocity() * dt, da2 = other.getAngularVelocity() * dt;
        double reach = BoundedAdvancement.reach(a, v1.x * dt, v1.y * dt, da1, b, v2.x * dt, v2.y * dt, da2, 0.0, 1.0);
        if (clearance.exceeds(mover, other, reach + BoundedAdvancement.ABSOLUTE_SLACK)) {
            return true;
        }
        // the test's answer: it stops at its first passing term, and the full clearance is their largest
        return clearance.measure(mover, a, mover.getPreviousTransform(), other, b, other.getPreviousTransform())
                - BoundedAdvancement.ABSOLUTE_SLACK > reach;
    }

    /** {@return how many times the pair was measured, and how many the remembered bound answered} */
    long[] counts() {
        return clearance.counts();
    }
}
