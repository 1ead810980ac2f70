package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.geometry.Circle;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Rectangle;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.junit.jupiter.api.Test;

/**
 * The sensors' ray casts against dyn4j's on random circles, rectangles and rays, many of them
 * starting inside, grazing or falling short: the closed-form circle and our GJK rectangle cast
 * give dyn4j's answers to the bit; the closed-form rectangle is exact, where GJK is not.
 */
class RayShapesTest {
    private final Gjk gjk = new Gjk();

    /** {@return dyn4j's distance, NaN for a miss} */
    private double dyn4j(Ray ray, double maxLength, org.dyn4j.geometry.Convex shape, Transform t) {
        Raycast result = new Raycast();
        return gjk.raycast(ray, maxLength, shape, t, result) ? result.getDistance() : Double.NaN;
    }

    private static Ray ray(double sx, double sy, double bearing) {
        return new Ray(new Vector2(sx, sy), bearing);
    }

    @Test
    void circlesGiveDyn4jsDistancesToTheBit() {
        var rnd = new Random(7);
        int hits = 0, misses = 0;
        for (int i = 0; i < 200_000; i++) {
            double cx = rnd.nextDouble() * 2 - 1, cy = rnd.nextDouble() * 2 - 1, r = 0.005 + rnd.nextDouble() * 0.1;
            double sx = rnd.nextDouble() * 2 - 1, sy = rnd.nextDouble() * 2 - 1;
            if (i % 4 == 0) { // aim near the circle, often grazing it
                double a = rnd.nextDouble() * 2 * Math.PI, k = r * (0.9 + rnd.nextDouble() * 0.2);
                sx = cx + k * Math.cos(a) + (rnd.nextDouble() - 0.5) * 0.3;
                sy = cy + k * Math.sin(a) + (rnd.nextDouble() - 0.5) * 0.3;
            }
            double bearing = i % 4 == 0 ? Math.atan2(cy - sy, cx - sx) + (rnd.nextDouble() - 0.5) * 0.4 : rnd.nextDouble() * 7 - 3.5;
            double maxLength = i % 8 == 0 ? 0.05 : 1.5;
            Ray ray = ray(sx, sy, bearing);
            Circle circle = Geometry.createCircle(r);
            Transform t = new Transform();
            t.setTranslation(cx, cy);
            t.setRotation(rnd.nextDouble() * 7);
            double expected = dyn4j(ray, maxLength, circle, t);
            Vector2 d = ray.getDirectionVector();
            double got = RayShapes.circle(sx, sy, d.x, d.y, cx, cy, r, maxLength);
            String where = "circle at (" + cx + ", " + cy + ") r " + r + ", ray from (" + sx + ", " + sy + ") at " + bearing
                    + ": dyn4j " + expected + ", closed form " + got;
            assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(got), where);
            if (Double.isNaN(expected)) {
                misses++;
            } else {
                hits++;
            }
        }
        assertTrue(hits > 20_000 && misses > 40_000, hits + " hits and " + misses + " misses: both were tried");
    }

    /** A random rectangle and ray, many of the rays aimed at it, some starting inside. */
    private record Case(double cx, double cy, double w, double h, double angle, double sx, double sy, double bearing,
                        double maxLength) {
        static Case random(Random rnd, int i) {
            double cx = rnd.nextDouble() * 2 - 1, cy = rnd.nextDouble() * 2 - 1;
            double w = 0.01 + rnd.nextDouble() * (i % 5 == 0 ? 2 : 0.2), h = 0.01 + rnd.nextDouble() * 0.2;
            double angle = i % 3 == 0 ? 0 : rnd.nextDouble() * 7 - 3.5; // walls and many boxes are not turned
            double sx = rnd.nextDouble() * 2 - 1, sy = rnd.nextDouble() * 2 - 1;
            if (i % 7 == 0) { // near or inside the rectangle
                sx = cx + (rnd.nextDouble() - 0.5) * w * 1.2;
                sy = cy + (rnd.nextDouble() - 0.5) * h * 1.2;
            }
            double bearing = i % 2 == 0 ? Math.atan2(cy - sy, cx - sx) + (rnd.nextDouble() - 0.5) * 0.6 : rnd.nextDouble() * 7 - 3.5;
            return new Case(cx, cy, w, h, angle, sx, sy, bearing, i % 8 == 0 ? 0.05 : 1.5);
        }

        Rectangle rectangle() {
            return Geometry.createRectangle(w, h);
        }

        Transform transform() {
            Transform t = new Transform();
            t.setTranslation(cx, cy);
            t.setRotation(angle);
            return t;
        }

        @Override
        public String toString() {
            return "rectangle " + w + " x " + h + " at (" + cx + ", " + cy + ") turned " + angle + ", ray from (" + sx + ", "
                    + sy + ") at " + bearing + " up to " + maxLength;
        }
    }

    @Test
    void theRectangleCastIsDyn4jsGjkCastToTheBit() {
        var rnd = new Random(3);
        int hits = 0, misses = 0;
        for (int i = 0; i < 300_000; i++) {
            Case c = Case.random(rnd, i);
            Ray ray = ray(c.sx, c.sy, c.bearing);
            Transform t = c.transform();
            double expected = dyn4j(ray, c.maxLength, c.rectangle(), t);
            Vector2 d = ray.getDirectionVector();
            double got = BoxGjkCast.cast(c.sx, c.sy, d.x, d.y, c.w, c.h, c.cx, c.cy, t.getCost(), t.getSint(), c.maxLength,
                    gjk.getRaycastEpsilon(), gjk.getMaxRaycastIterations());
            assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(got), c + ": dyn4j " + expected + ", ours " + got);
            if (Double.isNaN(expected)) {
                misses++;
            } else {
                hits++;
            }
        }
        assertTrue(hits > 40_000 && misses > 100_000, hits + " hits and " + misses + " misses: both were tried");
    }

    /**
     * The closed form is exact (it agrees with the ray's crossings of the four edges), and dyn4j's GJK
     * cast, which stops once within 0.12 mm of a chord, is off near the corners on a few rays in a
     * hundred: the rays' filter, which lets through every ray that passes within a millimetre of the
     * rectangle, never drops a ray GJK hits.
     */
    @Test
    void gjkIsOffNearCornersAndTheFilterKeepsEveryRayItHits() {
        var rnd = new Random(11);
        int hits = 0, misses = 0, gjkOff = 0, kept = 0;
        double worst = 0;
        for (int i = 0; i < 300_000; i++) {
            Case c = Case.random(rnd, i);
            Ray ray = ray(c.sx, c.sy, c.bearing);
            Rectangle rect = c.rectangle();
            Transform t = c.transform();
            Vector2 d = ray.getDirectionVector();
            double exact = RayShapes.box(c.sx, c.sy, d.x, d.y, c.cx, c.cy, t.getCost(), t.getSint(), c.w / 2, c.h / 2, c.maxLength);
            double edges = edges(c.sx, c.sy, d.x, d.y, rect, t, c.maxLength);
            assertEquals(Double.isNaN(edges), Double.isNaN(exact), c + ": edges " + edges + ", closed form " + exact);
            if (!Double.isNaN(exact)) {
                assertEquals(edges, exact, 1e-12, c.toString());
            }
            double gjkDistance = dyn4j(ray, c.maxLength, rect, t);
            boolean reach = RayShapes.boxReach(c.sx, c.sy, d.x, d.y, c.cx, c.cy, t.getCost(), t.getSint(), c.w / 2, c.h / 2,
                    1e-3, c.maxLength);
            if (!Double.isNaN(gjkDistance)) {
                hits++;
                assertTrue(reach, c + ": GJK hits at " + gjkDistance + " a ray the filter drops");
            } else {
                misses++;
            }
            kept += reach ? 1 : 0;
            boolean off = Double.isNaN(gjkDistance) != Double.isNaN(exact)
                    || !Double.isNaN(exact) && Math.abs(gjkDistance - exact) > 1e-9;
            if (off) {
                gjkOff++;
                if (!Double.isNaN(exact) && !Double.isNaN(gjkDistance)) {
                    worst = Math.max(worst, Math.abs(gjkDistance - exact));
                }
            }
        }
        assertTrue(hits > 40_000 && misses > 100_000, hits + " hits and " + misses + " misses: both were tried");
        assertTrue(gjkOff > 0 && gjkOff < hits / 50, gjkOff + " of " + hits + " GJK hits off by more than a nanometre");
        assertTrue(kept < hits + misses / 2, kept + " rays kept: the filter drops most misses");
        System.out.printf("rectangles: %d GJK hits, %d of them off the exact distance by more than 1 nm (at most %.3g m), "
                + "%d misses; the filter kept %d rays%n", hits, gjkOff, worst, misses, kept);
    }

    /** {@return the nearest crossing of the ray with the rectangle's four edges within maxLength, NaN for none or from inside} */
    private static double edges(double sx, double sy, double dx, double dy, Rectangle rect, Transform t, double maxLength) {
        if (rect.contains(new Vector2(sx, sy), t)) {
            return Double.NaN;
        }
        Vector2[] v = rect.getVertices();
        double best = Double.NaN;
        for (int k = 0; k < v.length; k++) {
            Vector2 p = t.getTransformed(v[k]), q = t.getTransformed(v[(k + 1) % v.length]);
            double ex = q.x - p.x, ey = q.y - p.y, den = dx * ey - dy * ex;
            if (den == 0) {
                continue;
            }
            double s = ((p.x - sx) * ey - (p.y - sy) * ex) / den, u = ((p.x - sx) * dy - (p.y - sy) * dx) / den;
            if (s >= 0 && u >= 0 && u <= 1 && s <= maxLength && !(s >= best)) {
                best = s;
            }
        }
        return best;
    }
}
