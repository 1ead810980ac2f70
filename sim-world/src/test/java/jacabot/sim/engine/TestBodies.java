package jacabot.sim.engine;

import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.MassType;

/** Bodies for the tests that compare our world's step with plain dyn4j's: the same body in either kind. */
final class TestBodies {
    private TestBodies() {
    }

    /** {@return a body of one fixture, ours (tracked) or dyn4j's own, damped as on the floor when movable, else fixed} */
    static Body of(boolean ours, Convex shape, double density, boolean movable) {
        Body b = ours ? new TrackedBody() : new Body();
        b.addFixture(shape).setDensity(density);
        if (movable) {
            b.setMass(MassType.NORMAL);
            b.setLinearDamping(Physics.FLOOR_DAMPING);
            b.setAngularDamping(Physics.FLOOR_DAMPING);
        } else {
            b.setMass(MassType.INFINITE);
        }
        return b;
    }
}
