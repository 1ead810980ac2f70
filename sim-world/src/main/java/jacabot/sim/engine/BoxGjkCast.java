package jacabot.sim.engine;

import org.dyn4j.Epsilon;

/**
 * dyn4j's GJK ray cast (its {@code Gjk.raycast} for polygons) worked out for a rectangle on plain
 * doubles: the same steps and the same floating-point operations in the same order, so the same
 * answer to the bit — including where GJK, stopping within its tolerance, is off the exact
 * distance near a corner, which the world's trajectories depend on. What it saves is the
 * allocation of a dozen vectors per iteration and the generic polygon code. Internal to sim-world;
 * RayShapesTest holds it to dyn4j's answers.
 */
final class BoxGjkCast {
    private BoxGjkCast() {
    }

    /**
     * {@return the distance along the ray at which GJK stops, or NaN where it answers a miss}
     *
     * @param sx        the ray's start
     * @param rx        the ray's unit direction, as dyn4j's {@code Ray} normalises it
     * @param w         the rectangle's full width (its own x), {@code h} its height
     * @param tx        the body's translation, {@code cos} and {@code sin} its rotation
     * @param maxLength the ray's length (> 0)
     * @param epsilon   the detector's raycast epsilon, compared with a squared distance as dyn4j does
     */
    static double cast(double sx, double sy, double rx, double ry, double w, double h, double tx, double ty, double cos,
                       double sin, double maxLength, double epsilon, int maxIterations) {
        // the vertices, counter-clockwise from the lower left, as dyn4j's Rectangle lists them
        double hx = w * 0.5, hy = h * 0.5;
        if (contains(sx, sy, hx, hy, tx, ty, cos, sin)) {
            return Double.NaN; // dyn4j answers no hit from inside
        }
        double cx = cos * 0.0 - sin * 0.0 + tx, cy = sin * 0.0 + cos * 0.0 + ty; // the centre, transformed
        double xx = sx, xy = sy; // the current point on the ray
        double dx = xx - cx, dy = xy - cy; // the search direction
        double lambda = 0;
        boolean hasA = false, hasB = false;
        double ax = 0, ay = 0, bx = 0, by = 0;
        double distanceSquared = Double.MAX_VALUE;
        int iterations = 0;
        while (distanceSquared > epsilon) {
            // the vertex farthest along d, found in the rectangle's frame, then put in the world's
            double lx = cos * dx + sin * dy, ly = -sin * dx + cos * dy;
            int k = farthest(lx, ly, hx, hy);
            double vx = vertexX(k, hx), vy = vertexY(k, hy);
            double px = cos * vx - sin * vy + tx, py = sin * vx + cos * vy + ty;
            double wx = xx - px, wy = xy - py;
            double dDotW = dx * wx + dy * wy;
            if (dDotW > 0.0) {
                double dDotR = dx * rx + dy * ry;
                if (dDotR >= 0.0) {
                    return Double.NaN; // the ray runs away from the rectangle
                }
                lambda = lambda - dDotW / dDotR;
                if (lambda > maxLength) {
                    return Double.NaN;
                }
                xx = rx * lambda + sx;
                xy = ry * lambda + sy;
            }
            if (hasA) {
                if (hasB) {
                    // keep the two of a, b, p whose segment lies nearest to x
                    double d1 = closestSquared(xx, xy, ax, ay, px, py), d2 = closestSquared(xx, xy, px, py, bx, by);
                    if (d1 < d2) {
                        bx = px;
                        by = py;
                        distanceSquared = d1;
                    } else {
                        ax = px;
                        ay = py;
                        distanceSquared = d2;
                    }
                } else {
                    bx = px;
                    by = py;
                    hasB = true;
                }
                // the new direction: across the segment ab, towards x (the triple product ab × ax × ab)
                double abx = bx - ax, aby = by - ay, axx = xx - ax, axy = xy - ay;
                double cross = abx * axy - axx * aby;
                dx = -aby * cross;
                dy = abx * cross;
            } else {
                ax = px;
                ay = py;
                hasA = true;
                dx = -dx;
                dy = -dy;
            }
            if (iterations == maxIterations) {
                return Double.NaN; // dyn4j gives up: no hit
            }
            iterations++;
        }
        return lambda;
    }

    private static double squared(double x, double y) {
        return x * x + y * y;
    }

    /** {@return vertex k's x: the rectangle's vertices go counter-clockwise from the lower left, as dyn4j lists them} */
    private static double vertexX(int k, double hx) {
        return k == 0 || k == 3 ? -hx : hx;
    }

    private static double vertexY(int k, double hy) {
        return k < 2 ? -hy : hy;
    }

    private static double along(double lx, double ly, int k, double hx, double hy) {
        return lx * vertexX(k, hx) + ly * vertexY(k, hy);
    }

    /**
     * The index of the vertex farthest along {@code (lx, ly)}: from vertex 0 up or down the list
     * while the projection grows, with dyn4j's strict and non-strict comparisons, which decide ties.
     */
    private static int farthest(double lx, double ly, double hx, double hy) {
        int n = 4, index = 0;
        double max = along(lx, ly, 0, hx, hy), candidate;
        if (max < (candidate = along(lx, ly, 1, hx, hy))) {
            do {
                max = candidate;
                index++;
            } while (index + 1 < n && max < (candidate = along(lx, ly, index + 1, hx, hy)));
        } else if (max < (candidate = along(lx, ly, n - 1, hx, hy))) {
            index = n;
            do {
                max = candidate;
                index--;
            } while (index > 0 && max <= (candidate = along(lx, ly, index - 1, hx, hy)));
        }
        return index;
    }

    /**
     * {@return the squared distance from (x, y) to its nearest point on the segment (ax, ay)-(bx, by)},
     * that point found as dyn4j finds it (clamped to the segment's ends)
     */
    private static double closestSquared(double x, double y, double ax, double ay, double bx, double by) {
        double tx = x - ax, ty = y - ay, lx = bx - ax, ly = by - ay;
        double length2 = lx * lx + ly * ly;
        double along = tx * lx + ty * ly;
        double qx = ax, qy = ay;
        if (length2 > Epsilon.E) {
            double t = along / length2;
            t = t <= 1.0 && t >= 0.0 ? t : 1.0 < t ? 1.0 : 0.0;
            qx = lx * t + ax;
            qy = ly * t + ay;
        }
        return squared(qx - x, qy - y);
    }

    /**
     * dyn4j's inclusive inside test for a rectangle: the start in the rectangle's frame, projected
     * on the edges from the first vertex, within half of each edge.
     */
    private static boolean contains(double sx, double sy, double hx, double hy, double tx, double ty, double cos,
                                    double sin) {
        double ox = sx - tx, oy = sy - ty;
        double px = cos * ox + sin * oy, py = -sin * ox + cos * oy;
        if (clearlyOutside(px, hx) || clearlyOutside(py, hy)) {
            return false;
        }
        double x0 = vertexX(0, hx), y0 = vertexY(0, hy), x1 = vertexX(1, hx), y1 = vertexY(1, hy);
        double x3 = vertexX(3, hx), y3 = vertexY(3, hy);
        double widthSquared = squared(x0 - x1, y0 - y1), heightSquared = squared(x0 - x3, y0 - y3);
        double e0x = x1 - x0, e0y = y1 - y0, e1x = x3 - x0, e1y = y3 - y0;
        double qx = px - 0.0, qy = py - 0.0; // from the centre, which is the origin of the frame
        return projectedSquared(qx, qy, e0x, e0y) <= widthSquared * 0.25
                && projectedSquared(qx, qy, e1x, e1y) <= heightSquared * 0.25;
    }

    /**
     * Whether a coordinate in the rectangle's frame lies clearly outside its slab {@code [-half, half]}:
     * the test below then fails too (it compares p² with half² after a few roundings, each a part in
     * 10^16), and its divisions are saved. Most casts start outside the rectangle.
     */
    private static boolean clearlyOutside(double p, double half) {
        return half > 1e-6 && Math.abs(p) > half * (1 + 1e-9);
    }

    /** {@return the squared length of (x, y) projected on (ex, ey)} */
    private static double projectedSquared(double x, double y, double ex, double ey) {
        double dot = x * ex + y * ey;
        double denominator = ex * ex + ey * ey;
        if (denominator <= Epsilon.E) {
            return 0;
        }
        double k = dot / denominator;
        return squared(k * ex, k * ey);
    }
}
