package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Penetration;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.Transform;
import org.junit.jupiter.api.Test;

/**
 * The narrow phase's test in front of GJK against GJK alone, on random circles and rectangles from
 * far apart to overlapping, many a hair apart.
 */
class BoundedGjkTest {
    private final Random rnd = new Random(5);

    private Convex shape() {
        return rnd.nextBoolean()
                ? Geometry.createCircle(0.005 + rnd.nextDouble() * 0.1)
                : Geometry.createRectangle(0.005 + rnd.nextDouble() * 0.3, 0.005 + rnd.nextDouble() * 0.3);
    }

    private Transform placed(double spread) {
        Transform t = new Transform();
        t.rotate(rnd.nextInt(4) == 0 ? 0 : rnd.nextDouble() * 2 * Math.PI);
        t.translate((rnd.nextDouble() * 2 - 1) * spread, (rnd.nextDouble() * 2 - 1) * spread);
        return t;
    }

    @Test
    void answersAsGjkDoes() {
        var ours = new BoundedGjk();
        var gjk = new Gjk();
        int touching = 0, close = 0;
        for (int i = 0; i < 300_000; i++) {
            Convex a = shape(), b = shape();
            Transform ta = placed(0.3), tb = placed(0.3);
            if (rnd.nextBoolean()) { // slide b along the line of centres until the shapes are about to touch
                double dx = tb.getTranslationX() - ta.getTranslationX(), dy = tb.getTranslationY() - ta.getTranslationY();
                double d = Math.sqrt(dx * dx + dy * dy);
                double gap = BoundedAdvancement.clearance(a, ta, b, tb) - rnd.nextDouble() * 1e-5;
                if (d > 0 && gap > 0) {
                    tb.translate(-dx / d * gap, -dy / d * gap);
                    close++;
                }
            }
            Penetration expected = new Penetration(), actual = new Penetration();
            boolean hit = gjk.detect(a, ta, b, tb, expected);
            assertEquals(hit, ours.detect(a, ta, b, tb, actual), "pair " + i);
            assertEquals(gjk.detect(a, ta, b, tb), ours.detect(a, ta, b, tb), "pair " + i);
            if (hit) {
                touching++;
                assertEquals(expected.getDepth(), actual.getDepth(), 0.0, "pair " + i);
                assertEquals(expected.getNormal(), actual.getNormal(), "pair " + i);
            }
        }
        // overlapping, apart and a hair apart all came up often
        assertTrue(touching > 20_000 && touching < 280_000, "touching " + touching);
        assertTrue(close > 50_000, "close " + close);
    }
}
