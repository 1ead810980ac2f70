package jacabot.sim.engine;

/**
 * Rays against the world's two shapes, solved in closed form instead of by dyn4j's iterative GJK
 * cast. Both take a ray start {@code (sx, sy)} and a unit direction {@code (dx, dy)} and {@return
 * the distance along the ray to the shape's outline, or NaN for a miss} — a miss also when the
 * ray starts inside the shape or meets it farther than {@code maxLength}, as dyn4j's casts answer.
 * Internal to sim-world.
 */
final class RayShapes {
    private RayShapes() {
    }

    /**
     * A circle of radius {@code r} centred on {@code (cx, cy)}: the smaller non-negative root of
     * |s + t d - c|² = r². The terms are formed in the order dyn4j's circle cast forms them, so the
     * distance is the same to the last bit.
     */
    static double circle(double sx, double sy, double dx, double dy, double cx, double cy, double r, double maxLength) {
        double mx = sx - cx, my = sy - cy; // from the centre to the start
        double m2 = mx * mx + my * my;
        double r2 = r * r;
        if (m2 <= r2) {
            return Double.NaN; // starts inside (or on) the circle
        }
        double a = dx * dx + dy * dy;
        double b = 2 * (dx * mx + dy * my);
        double c = m2 - r2;
        double inv2a = 1.0 / (2.0 * a);
        double disc = b * b - 4 * a * c;
        if (disc < 0.0) {
            return Double.NaN;
        }
        double root = Math.sqrt(disc);
        double far = (-b + root) * inv2a, near = (-b - root) * inv2a;
        double t;
        if (far < 0.0) {
            if (near < 0.0) {
                return Double.NaN; // the circle is behind the start
            }
            t = near;
        } else if (near < 0.0 || far < near) {
            t = far;
        } else {
            t = near;
        }
        return maxLength > 0.0 && t > maxLength ? Double.NaN : t;
    }

    /**
     * {@return whether a ray from {@code (sx, sy)} can come within {@code margin} of a rectangle
     * within {@code maxLength}}: it starts in, or crosses, the rectangle grown by {@code margin} on
     * every side. A conservative filter for casts that stop within a tolerance of the outline.
     */
    static boolean boxReach(double sx, double sy, double dx, double dy, double cx, double cy, double cos, double sin,
                            double hx, double hy, double margin, double maxLength) {
        return !Double.isNaN(boxReachFrom(sx, sy, dx, dy, cx, cy, cos, sin, hx, hy, margin, maxLength));
    }

    /**
     * As {@link #boxReach}, with where: {@return the distance along the ray at which it enters the
     * rectangle grown by {@code margin} (0 when it starts inside), or NaN when it does not reach it}.
     * A cast that stops within the margin of the outline stops no nearer than that.
     */
    static double boxReachFrom(double sx, double sy, double dx, double dy, double cx, double cy, double cos, double sin,
                               double hx, double hy, double margin, double maxLength) {
        double gx = hx + margin, gy = hy + margin;
        double ox = sx - cx, oy = sy - cy;
        if (Math.abs(cos * ox + sin * oy) <= gx && Math.abs(-sin * ox + cos * oy) <= gy) {
            return 0;
        }
        return box(sx, sy, dx, dy, cx, cy, cos, sin, gx, gy, maxLength);
    }

    /**
     * {@return the distance from the point {@code (px, py)} to a rectangle of half sizes
     * {@code hx × hy} centred on {@code (cx, cy)}, its own x axis at {@code (cos, sin)}} (0 inside)
     */
    static double boxDistance(double px, double py, double cx, double cy, double cos, double sin, double hx, double hy) {
        double ox = px - cx, oy = py - cy;
        double qx = Math.max(Math.abs(cos * ox + sin * oy) - hx, 0), qy = Math.max(Math.abs(-sin * ox + cos * oy) - hy, 0);
        return Math.sqrt(qx * qx + qy * qy);
    }

    /**
     * A rectangle of half sizes {@code hx × hy} centred on {@code (cx, cy)}, its own x axis at
     * {@code (cos, sin)}: the slab test in the rectangle's frame, where the ray enters the last of
     * its two slabs before it leaves either.
     */
    static double box(double sx, double sy, double dx, double dy, double cx, double cy, double cos, double sin,
                      double hx, double hy, double maxLength) {
        double ox = sx - cx, oy = sy - cy;
        double lx = cos * ox + sin * oy, ly = -sin * ox + cos * oy; // the start in the rectangle's frame
        if (Math.abs(lx) <= hx && Math.abs(ly) <= hy) {
            return Double.NaN; // starts inside (or on) the rectangle
        }
        double ux = cos * dx + sin * dy, uy = -sin * dx + cos * dy; // the direction in that frame
        double enter = Double.NEGATIVE_INFINITY, leave = Double.POSITIVE_INFINITY;
        if (ux == 0.0) {
            if (Math.abs(lx) > hx) {
                return Double.NaN; // parallel to the x slab and outside it
            }
        } else {
            double t1 = (-hx - lx) / ux, t2 = (hx - lx) / ux;
            enter = Math.min(t1, t2);
            leave = Math.max(t1, t2);
        }
        if (uy == 0.0) {
            if (Math.abs(ly) > hy) {
                return Double.NaN;
            }
        } else {
            double t1 = (-hy - ly) / uy, t2 = (hy - ly) / uy;
            enter = Math.max(enter, Math.min(t1, t2));
            leave = Math.min(leave, Math.max(t1, t2));
        }
        if (enter > leave || enter < 0.0) {
            return Double.NaN; // misses, or the rectangle is behind the start
        }
        return maxLength > 0.0 && enter > maxLength ? Double.NaN : enter;
    }
}
