package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.dyn4j.collision.continuous.ConservativeAdvancement;
import org.dyn4j.collision.continuous.TimeOfImpact;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.junit.jupiter.api.Test;

/**
 * A pair that remembers its clearance against the plain test and dyn4j's conservative advancement,
 * on random walks of two bodies (circles and rectangles, turning as well as moving) that drift
 * towards and away from each other: where the pair measures, its answer is the test's; where it
 * answers from memory, dyn4j's detector answers no impact. Likewise the narrow phase with a
 * penetration that remembers the clearance, against GJK alone.
 */
class ClearancePairTest {
    private final Random rnd = new Random(23);

    private Convex shape() {
        return rnd.nextBoolean()
                ? Geometry.createCircle(0.02 + rnd.nextDouble() * 0.3)
                : Geometry.createRectangle(0.02 + rnd.nextDouble() * 2, 0.02 + rnd.nextDouble() * 0.5);
    }

    /** A body as a world holds it: {@link TrackedBody#joined()} keeps the extent its odometer counts rotations by. */
    private static TrackedBody tracked(Convex shape, boolean movable) {
        var body = (TrackedBody) TestBodies.of(true, shape, 1, movable);
        body.joined();
        return body;
    }

    @Test
    void answersFromMemoryOnlyWhereDyn4jFindsNoImpact() {
        var dyn4j = new ConservativeAdvancement();
        double dt = 0.01;
        long beyondTest = 0, steps = 0, impacts = 0, remembered = 0;
        for (int walk = 0; walk < 400; walk++) {
            var mover = tracked(shape(), true);
            var other = tracked(shape(), rnd.nextBoolean());
            other.translate(rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 3 - 1.5);
            other.rotate(rnd.nextDouble() * 6);
            mover.rotate(rnd.nextDouble() * 6);
            var pair = rnd.nextBoolean() ? new ClearancePair(mover, other) : new ClearancePair(other, mover);
            for (int step = 0; step < 1_000; step++) {
                // drift towards the other body, with noise; now and then a jump (a teleport) or a spin
                Vector2 to = other.getTransform().getTranslation().difference(mover.getTransform().getTranslation());
                double speed = rnd.nextDouble() * 2;
                double vx = to.x * speed + rnd.nextGaussian(), vy = to.y * speed + rnd.nextGaussian();
                mover.setLinearVelocity(vx, vy);
                mover.setAngularVelocity(rnd.nextInt(4) == 0 ? rnd.nextGaussian() * 3 : 0);
                other.setLinearVelocity(rnd.nextGaussian() * 0.2, rnd.nextGaussian() * 0.2);
                other.setAngularVelocity(rnd.nextInt(4) == 0 ? rnd.nextGaussian() : 0);
                mover.getPreviousTransform().set(mover.getTransform());
                other.getPreviousTransform().set(other.getTransform());
                mover.countMotion(); // as the world counts at a step's start
                other.countMotion();
                boolean ours = pair.cannotMeet(mover, other, dt);
                boolean test = Dyn4jWorld.cannotMeet(mover, other, dt);
                Transform ta = mover.getPreviousTransform(), tb = other.getPreviousTransform();
                Vector2 dpa = mover.getLinearVelocity().product(dt), dpb = other.getLinearVelocity().product(dt);
                double daa = mover.getAngularVelocity() * dt, dab = other.getAngularVelocity() * dt;
                boolean hit = dyn4j.getTimeOfImpact(mover.getFixture(0).getShape(), ta, dpa, daa,
                        other.getFixture(0).getShape(), tb, dpb, dab, 0.0, 1.0, new TimeOfImpact());
                if (hit) {
                    impacts++;
                    assertFalse(ours, "walk " + walk + ", step " + step + ": answered from memory where dyn4j finds an impact");
                }
                if (ours && !test) {
                    beyondTest++; // the remembered bound is no test's: dyn4j's detector, above, decides
                } else {
                    assertEquals(test, ours, "walk " + walk + ", step " + step);
                }
                steps++;
                // the step's motion, and now and then a jump
                mover.translate(vx * dt, vy * dt);
                mover.rotate(mover.getAngularVelocity() * dt, mover.getTransform().getTranslation());
                other.translate(other.getLinearVelocity().product(dt));
                other.rotate(other.getAngularVelocity() * dt, other.getTransform().getTranslation());
                if (rnd.nextInt(200) == 0) {
                    mover.translate(rnd.nextGaussian() * 0.3, rnd.nextGaussian() * 0.3);
                }
                if (rnd.nextInt(200) == 0) {
                    other.rotate(rnd.nextGaussian(), other.getTransform().getTranslation());
                }
            }
            remembered += pair.counts()[1];
        }
        // both roads often: answers from memory, and real impacts met
        assertTrue(impacts > 2_000, "impacts " + impacts);
        assertTrue(remembered > 50_000, "answered from memory " + remembered + " of " + steps + ", beyond the test " + beyondTest);
    }

    @Test
    void theNarrowPhaseAnswersAsGjkWithARememberedClearance() {
        var ours = new BoundedGjk();
        var gjk = new Gjk();
        long touching = 0, remembered = 0;
        for (int walk = 0; walk < 300; walk++) {
            Convex a = shape(), b = shape();
            var bodyA = tracked(a, true);
            var bodyB = tracked(b, false);
            Transform ta = bodyA.getTransform(), tb = bodyB.getTransform();
            tb.translate(rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 3 - 1.5);
            tb.rotate(rnd.nextDouble() * 6, tb.getTranslation());
            var penetration = new ClearancePenetration(bodyA, bodyB);
            for (int step = 0; step < 1_000; step++) {
                Vector2 to = tb.getTranslation().difference(ta.getTranslation());
                ta.translate(to.x * rnd.nextDouble() * 0.02 + rnd.nextGaussian() * 0.01, to.y * rnd.nextDouble() * 0.02 + rnd.nextGaussian() * 0.01);
                if (rnd.nextInt(4) == 0) {
                    ta.rotate(rnd.nextGaussian() * 0.05, ta.getTranslation());
                }
                if (rnd.nextInt(200) == 0) {
                    tb.rotate(rnd.nextGaussian(), tb.getTranslation());
                }
                bodyA.countMotion();
                bodyB.countMotion();
                var expected = new Penetration();
                boolean hit = gjk.detect(a, ta, b, tb, expected);
                assertEquals(hit, ours.detect(a, ta, b, tb, penetration), "walk " + walk + ", step " + step);
                if (hit) {
                    touching++;
                    assertEquals(expected.getDepth(), penetration.getDepth(), 0.0);
                    assertEquals(expected.getNormal(), penetration.getNormal());
                }
            }
            remembered += penetration.clearance.counts()[1];
        }
        assertTrue(touching > 2_000, "touching " + touching);
        assertTrue(remembered > 20_000, "answered from memory " + remembered);
    }

    /** The world's counts pass a fixed body by: its teleport counts its motion, rotation included. */
    @Test
    void aFixedBodyCountsItsTeleports() {
        var fixed = tracked(Geometry.createRectangle(2, 0.5), false);
        var moving = tracked(Geometry.createRectangle(2, 0.5), true);
        fixed.translate(0.3, 0.4);
        fixed.rotate(Math.PI / 2, fixed.getTransform().getTranslation());
        fixed.teleported();
        // the end of the 2 m box swings by 1 m * sqrt(2) on top of the 0.5 m translation
        assertTrue(fixed.odometer >= 0.5 + Math.sqrt(2) - 1e-12, "odometer " + fixed.odometer);
        moving.translate(0.3, 0.4);
        moving.teleported();
        assertEquals(0.0, moving.odometer, "a moving body is counted by the world's step");
        moving.countMotion();
        assertEquals(0.5, moving.odometer, 1e-12);
    }
}
