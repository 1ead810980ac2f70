package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Random;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.joint.DistanceJoint;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;
import org.junit.jupiter.api.Test;

/**
 * {@link Islands} against dyn4j's own island walk: a crowd of movable boxes and cylinders between
 * fixed posts, pushed into heaps by discs, so that islands hold many moving bodies and share fixed
 * ones, stepped by {@link Dyn4jWorld} and by dyn4j's world as it comes; every body must be the same
 * to the bit at every step. With a joint, dyn4j's walk runs, and still gives the same steps.
 */
class IslandsTest {
    private static final int STEPS = 600;

    private static World<Body> crowd(boolean ours, boolean joint) {
        World<Body> world = ours ? new Dyn4jWorld() : new World<>();
        world.setGravity(World.ZERO_GRAVITY);
        world.getSettings().setStepFrequency(0.008);
        world.getSettings().setAtRestDetectionEnabled(false);
        Random rnd = new Random(11);
        for (double[] w : new double[][] {{0.51, 0, 0.02, 1.04}, {-0.51, 0, 0.02, 1.04}, {0, 0.51, 1.0, 0.02}, {0, -0.51, 1.0, 0.02}}) {
            world.addBody(body(ours, Geometry.createRectangle(w[2], w[3]), w[0], w[1], false));
        }
        for (int i = 0; i < 12; i++) { // fixed posts, which the heaps' islands share
            world.addBody(body(ours, Geometry.createRectangle(0.03, 0.03), rnd.nextDouble() * 0.8 - 0.4, rnd.nextDouble() * 0.8 - 0.4, false));
        }
        for (int i = 0; i < 40; i++) {
            boolean box = i % 3 != 0;
            world.addBody(body(ours, box ? Geometry.createRectangle(0.04, 0.04) : Geometry.createCircle(0.02),
                    rnd.nextDouble() * 0.8 - 0.4, rnd.nextDouble() * 0.8 - 0.4, true));
        }
        for (int i = 0; i < 4; i++) {
            Body disc = ours ? new TrackedBody() : new Body();
            disc.addFixture(Geometry.createCircle(0.035)).setFriction(0);
            disc.getFixture(0).setDensity(50 / (Math.PI * 0.035 * 0.035));
            disc.setMass(MassType.FIXED_ANGULAR_VELOCITY);
            disc.setLinearDamping(0);
            disc.setAngularDamping(0);
            disc.translate(0.4 * Math.cos(i * Math.PI / 2), 0.4 * Math.sin(i * Math.PI / 2));
            world.addBody(disc);
        }
        if (joint) {
            world.addJoint(new DistanceJoint<>(world.getBody(20), world.getBody(21),
                    world.getBody(20).getWorldCenter(), world.getBody(21).getWorldCenter()));
        }
        return world;
    }

    private static Body body(boolean ours, org.dyn4j.geometry.Convex shape, double x, double y, boolean movable) {
        Body b = TestBodies.of(ours, shape, 1, movable);
        b.translate(x, y);
        return b;
    }

    /** Steps both worlds, the discs driving towards the centre and about; {@return the most bodies in contact with one} */
    private static int stepBoth(World<Body> plain, World<Body> ours) {
        Random drive = new Random(5);
        int most = 0;
        for (int step = 0; step < STEPS; step++) {
            if (step % 50 == 0) {
                for (int r = plain.getBodyCount() - 4; r < plain.getBodyCount(); r++) {
                    Vector2 at = plain.getBody(r).getWorldCenter();
                    double vx = -at.x + drive.nextDouble() * 0.4 - 0.2, vy = -at.y + drive.nextDouble() * 0.4 - 0.2;
                    plain.getBody(r).setLinearVelocity(vx, vy);
                    ours.getBody(r).setLinearVelocity(vx, vy);
                }
            }
            plain.step(1);
            ours.step(1);
            for (int i = 0; i < plain.getBodyCount(); i++) {
                Body a = plain.getBody(i), b = ours.getBody(i);
                if (!(a.getTransform().getTranslationX() == b.getTransform().getTranslationX()
                        && a.getTransform().getTranslationY() == b.getTransform().getTranslationY()
                        && a.getTransform().getCost() == b.getTransform().getCost()
                        && a.getTransform().getSint() == b.getTransform().getSint()
                        && a.getLinearVelocity().equals(b.getLinearVelocity()) && a.getAngularVelocity() == b.getAngularVelocity())) {
                    fail("step " + step + ", body " + i + ": " + a.getTransform() + " against " + b.getTransform());
                }
                most = Math.max(most, plain.getInContactBodies(a, false).size());
            }
        }
        return most;
    }

    @Test
    void heapsAreSolvedAsDyn4jSolvesThem() {
        World<Body> plain = crowd(false, false), ours = crowd(true, false);
        int most = stepBoth(plain, ours);
        assertTrue(most >= 4, "some body touched " + most + " others at once");
        assertEquals(STEPS, ((Dyn4jWorld) ours).islandSteps());
    }

    @Test
    void theWorldTakesTrackedBodiesOnly() {
        World<Body> ours = new Dyn4jWorld();
        assertThrows(IllegalArgumentException.class, () -> ours.addBody(new Body()));
        ours.addBody(new TrackedBody());
        assertEquals(1, ours.getBodyCount());
    }

    @Test
    void aWorldWithJointsKeepsDyn4jsWalk() {
        World<Body> plain = crowd(false, true), ours = crowd(true, true);
        stepBoth(plain, ours);
        assertEquals(0, ((Dyn4jWorld) ours).islandSteps());
    }
}
