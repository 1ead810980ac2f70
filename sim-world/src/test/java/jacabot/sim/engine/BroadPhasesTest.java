package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Random;
import org.dyn4j.dynamics.Body;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.world.World;
import org.dyn4j.world.WorldCollisionData;
import org.junit.jupiter.api.Test;

/**
 * The same cluttered arena stepped twice, by dyn4j as it comes and with {@link BroadPhases}: every
 * body's transform and velocity must be the same to the bit at every step, while discs driven at
 * random push boxes and cylinders into fixed boxes and walls, one box is removed and one fixed box is
 * teleported into their way. The broad phases must keep dyn4j's pairs, in its order, less the pairs of two fixed bodies.
 */
class BroadPhasesTest {
    private static final int STEPS = 1_500;

    /** A world as {@link Physics} sets it up ({@link Dyn4jWorld}, its broad phases), or dyn4j's as it comes, with the same bodies. */
    private static World<Body> arena(boolean ours) {
        World<Body> world = ours ? new Dyn4jWorld() : new World<>();
        world.setGravity(World.ZERO_GRAVITY);
        world.getSettings().setStepFrequency(0.008);
        world.getSettings().setAtRestDetectionEnabled(false);
        world.setTimeOfImpactDetector(new BoundedAdvancement());
        if (ours) {
            BroadPhases.install(world);
        }
        Random rnd = new Random(3);
        for (double[] w : new double[][] {{1.01, 0, 0.02, 2.04}, {-1.01, 0, 0.02, 2.04}, {0, 1.01, 2.0, 0.02}, {0, -1.01, 2.0, 0.02}}) {
            world.addBody(box(ours, w[0], w[1], w[2], w[3], 0, false));
        }
        for (int i = 0; i < 60; i++) {
            boolean movable = i % 4 == 0;
            world.addBody(box(ours, rnd.nextDouble() * 1.8 - 0.9, rnd.nextDouble() * 1.8 - 0.9, 0.03 + rnd.nextDouble() * 0.08,
                    0.03 + rnd.nextDouble() * 0.08, rnd.nextDouble() * Math.PI, movable));
        }
        for (int i = 0; i < 6; i++) {
            Body c = body(ours);
            c.addFixture(Geometry.createCircle(0.02)).setDensity(0.1 / (Math.PI * 0.0004));
            c.setMass(MassType.NORMAL);
            c.setLinearDamping(Physics.FLOOR_DAMPING);
            c.setAngularDamping(Physics.FLOOR_DAMPING);
            c.translate(rnd.nextDouble() * 1.8 - 0.9, rnd.nextDouble() * 1.8 - 0.9);
            world.addBody(c);
        }
        for (int i = 0; i < 3; i++) {
            Body robot = body(ours);
            robot.addFixture(Geometry.createCircle(0.035)).setFriction(0);
            robot.getFixture(0).setDensity(50 / (Math.PI * 0.035 * 0.035));
            robot.setMass(MassType.FIXED_ANGULAR_VELOCITY);
            robot.setLinearDamping(0);
            robot.setAngularDamping(0);
            robot.translate(-0.6 + 0.6 * i, 0.95 - 0.9 * i);
            world.addBody(robot);
        }
        return world;
    }

    /** A body as dyn4j makes it, or as {@link Physics} does for its broad phases. */
    private static Body body(boolean ours) {
        return ours ? new TrackedBody() : new Body();
    }

    private static Body box(boolean ours, double x, double y, double w, double h, double angle, boolean movable) {
        Body b = TestBodies.of(ours, Geometry.createRectangle(w, h), 0.3 / (w * h), movable);
        b.rotate(angle);
        b.translate(x, y);
        return b;
    }

    @Test
    void trajectoriesAreDyn4jsToTheBit() {
        World<Body> plain = arena(false), ours = arena(true);
        Random drive = new Random(8);
        int contacts = 0;
        for (int step = 0; step < STEPS; step++) {
            if (step % 60 == 0) { // the discs pick new velocities, fast enough to push and bounce
                for (int r = plain.getBodyCount() - 3; r < plain.getBodyCount(); r++) {
                    double vx = drive.nextDouble() * 0.6 - 0.3, vy = drive.nextDouble() * 0.6 - 0.3;
                    plain.getBody(r).setLinearVelocity(vx, vy);
                    ours.getBody(r).setLinearVelocity(vx, vy);
                }
            }
            if (step == STEPS / 3) { // the supervisor removes a box: its pairs go
                plain.removeBody(10);
                ours.removeBody(10);
            }
            if (step == STEPS / 2) { // the supervisor teleports a fixed box next to a disc
                for (World<Body> w : List.of(plain, ours)) {
                    Body robot = w.getBody(w.getBodyCount() - 1);
                    w.getBody(5).getTransform().setTranslation(robot.getTransform().getTranslationX() + 0.1,
                            robot.getTransform().getTranslationY());
                    if (w.getBody(5) instanceof TrackedBody t) {
                        t.teleported(); // as SimObject.place says it
                    }
                }
            }
            plain.step(1);
            ours.step(1);
            for (int i = 0; i < plain.getBodyCount(); i++) {
                if (!same(plain.getBody(i), ours.getBody(i))) {
                    fail("step " + step + ", body " + i + ": " + plain.getBody(i).getTransform() + " against " + ours.getBody(i).getTransform());
                }
            }
            for (int r = plain.getBodyCount() - 3; r < plain.getBodyCount(); r++) {
                contacts += plain.getInContactBodies(plain.getBody(r), false).size();
            }
        }
        assertTrue(contacts > 500, "the discs touched something in " + contacts + " body-steps");
        assertEquals(STEPS, ((Dyn4jWorld) ours).islandSteps(), "the islands were walked by Islands, not by dyn4j");
        long impacts = ((Dyn4jWorld) ours).impacts();
        assertTrue(impacts > 20, "the time-of-impact pass moved a body back " + impacts + " times");
        // the teleported box was seen where it went: something touched it afterwards
        List<Body> touching = new ArrayList<>(ours.getInContactBodies(ours.getBody(5), false));
        assertEquals(new ArrayList<>(plain.getInContactBodies(plain.getBody(5), false)).size(), touching.size());
    }

    @Test
    void keepsDyn4jsPairsInOrderLessThoseOfTwoFixedBodies() {
        World<Body> plain = arena(false), ours = arena(true);
        for (int step = 0; step < 50; step++) {
            plain.step(1);
            ours.step(1);
        }
        List<String> expected = new ArrayList<>();
        int fixedPairs = 0;
        for (Iterator<WorldCollisionData<Body>> it = plain.getCollisionDataIterator(); it.hasNext(); ) {
            WorldCollisionData<Body> d = it.next();
            if (BroadPhases.fixed(d.getBody1()) && BroadPhases.fixed(d.getBody2())) {
                fixedPairs++;
            } else {
                expected.add(pair(plain, d));
            }
        }
        List<String> kept = new ArrayList<>();
        for (Iterator<WorldCollisionData<Body>> it = ours.getCollisionDataIterator(); it.hasNext(); ) {
            kept.add(pair(ours, it.next()));
        }
        assertTrue(fixedPairs > 50, "dyn4j kept " + fixedPairs + " pairs of two fixed bodies");
        assertFalse(expected.isEmpty());
        assertEquals(expected, kept);
    }

    private static boolean same(Body a, Body b) {
        return a.getTransform().getTranslationX() == b.getTransform().getTranslationX()
                && a.getTransform().getTranslationY() == b.getTransform().getTranslationY()
                && a.getTransform().getCost() == b.getTransform().getCost() && a.getTransform().getSint() == b.getTransform().getSint()
                && a.getLinearVelocity().equals(b.getLinearVelocity()) && a.getAngularVelocity() == b.getAngularVelocity();
    }

    /** {@return a pair named by its bodies' places in the world, the same in both worlds} */
    private static String pair(World<Body> world, WorldCollisionData<Body> d) {
        return world.getBodies().indexOf(d.getBody1()) + "-" + world.getBodies().indexOf(d.getBody2());
    }
}
