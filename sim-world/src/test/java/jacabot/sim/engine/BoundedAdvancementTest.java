package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.dyn4j.collision.continuous.ConservativeAdvancement;
import org.dyn4j.collision.continuous.TimeOfImpact;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Separation;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.junit.jupiter.api.Test;

/**
 * The time-of-impact test in front of dyn4j's conservative advancement against dyn4j alone, on
 * random circles and rectangles moving by up to their own size, many of them touching or about to.
 */
class BoundedAdvancementTest {
    private final Random rnd = new Random(11);

    private Convex shape() {
        return rnd.nextBoolean()
                ? Geometry.createCircle(0.01 + rnd.nextDouble() * 0.3)
                : Geometry.createRectangle(0.01 + rnd.nextDouble() * 2, 0.01 + rnd.nextDouble() * 2);
    }

    private Transform placed(double spread) {
        Transform t = new Transform();
        t.rotate(rnd.nextDouble() * 2 * Math.PI);
        t.translate((rnd.nextDouble() * 2 - 1) * spread, (rnd.nextDouble() * 2 - 1) * spread);
        return t;
    }

    private Vector2 motion(double scale) {
        return rnd.nextInt(5) == 0 ? new Vector2() : new Vector2((rnd.nextDouble() * 2 - 1) * scale, (rnd.nextDouble() * 2 - 1) * scale);
    }

    private double turn() {
        return rnd.nextInt(3) == 0 ? 0 : (rnd.nextDouble() * 2 - 1) * 0.3;
    }

    @Test
    void answersAsConservativeAdvancementDoes() {
        var ours = new BoundedAdvancement();
        var dyn4j = new ConservativeAdvancement();
        int impacts = 0;
        for (int i = 0; i < 300_000; i++) {
            Convex a = shape(), b = shape();
            double spread = 0.2 + rnd.nextDouble() * 2;
            Transform ta = placed(spread), tb = placed(spread);
            Vector2 dpa = motion(rnd.nextDouble() * spread), dpb = motion(rnd.nextDouble() * 0.2);
            double daa = turn(), dab = turn();
            double t2 = rnd.nextInt(3) == 0 ? 1.0 : rnd.nextDouble();
            TimeOfImpact expected = new TimeOfImpact(), actual = new TimeOfImpact();
            boolean hit = dyn4j.getTimeOfImpact(a, ta, dpa, daa, b, tb, dpb, dab, 0.0, t2, expected);
            assertEquals(hit, ours.getTimeOfImpact(a, ta, dpa, daa, b, tb, dpb, dab, 0.0, t2, actual), "pair " + i);
            if (hit) {
                impacts++;
                assertEquals(expected.getTime(), actual.getTime(), 0.0, "pair " + i);
                assertEquals(expected.getSeparation().getDistance(), actual.getSeparation().getDistance(), 0.0, "pair " + i);
            }
        }
        // both roads were taken often: the test would catch a bound that answers a real impact
        assertTrue(impacts > 5_000, "impacts " + impacts);
        assertTrue(ours.skipped() > 50_000, "skipped " + ours.skipped());
    }

    @Test
    void clearanceNeverExceedsTheDistance() {
        var gjk = new Gjk();
        int separated = 0;
        for (int i = 0; i < 300_000; i++) {
            Convex a = shape(), b = shape();
            Transform ta = placed(1.5), tb = placed(1.5);
            var s = new Separation();
            double bound = BoundedAdvancement.clearance(a, ta, b, tb);
            if (gjk.distance(a, ta, b, tb, s)) {
                separated++;
                assertTrue(bound <= s.getDistance() + 1e-12, "pair " + i + ": " + bound + " > " + s.getDistance());
            } else {
                assertTrue(bound <= 1e-12, "pair " + i + " overlaps, bound " + bound);
            }
        }
        assertTrue(separated > 50_000, "separated " + separated);
    }
}
