package jacabot.experiments;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The points a front sensor read close by in the last few seconds, kept in the dead-reckoning frame
 * (not in the thesis): a turn on the spot brings a box the sensor swept past to the body's flank,
 * out of both cones, and the drive after the turn touched it. A strong reading places its point
 * well (all three rays meet the box), and a turn on the spot keeps its distance from the centre, so
 * the turn can go on until no such point is left in the strip the body sweeps as it drives ahead.
 * Angles in this class are radians, left turns positive, as in {@link ExplorationMap}.
 */
final class NearPoints {
    /** The step in which {@link #turnPast} tries more turn, degrees. */
    static final double STEP = 5;

    private record Point(double x, double z, long timeMs) {}

    private final long windowMs;
    private final Deque<Point> points = new ArrayDeque<>(); // oldest first

    /** @param windowMs how long a point is kept, ms */
    NearPoints(long windowMs) {
        if (windowMs <= 0) {
            throw new IllegalArgumentException("the window must be positive, got " + windowMs);
        }
        this.windowMs = windowMs;
    }

    /** Keeps the point {@code (x, z)} read at {@code nowMs}. */
    void add(double x, double z, long nowMs) {
        points.addLast(new Point(x, z, nowMs));
        forget(nowMs);
    }

    private void forget(long nowMs) {
        while (!points.isEmpty() && points.peekFirst().timeMs() < nowMs - windowMs) {
            points.removeFirst();
        }
    }

    /** {@return how many points are kept at {@code nowMs}} */
    int size(long nowMs) {
        forget(nowMs);
        return points.size();
    }

    /**
     * {@return the least further turn on the spot, degrees (a multiple of {@link #STEP}, at most
     * {@code maxDegrees}), towards the left or the right, after which no kept point lies in the strip
     * a body of {@code radius} metres sweeps ahead, {@code margin} wider each side and up to
     * {@code reach} beyond its rim; 0 when none lies there now, -1 when no turn up to {@code maxDegrees} clears}
     */
    double turnPast(double x, double z, double heading, boolean left, double radius, double margin, double reach,
                    double maxDegrees, long nowMs) {
        forget(nowMs);
        for (double k = 0; k <= maxDegrees + 1e-9; k += STEP) {
            double h = heading + Math.toRadians(left ? k : -k);
            if (!anyAhead(x, z, h, radius, margin, reach)) {
                return k;
            }
        }
        return -1;
    }

    /**
     * {@return whether a kept point lies in the strip a body of {@code radius} metres sweeps backing
     * up to {@code reach} beyond its rim, {@code margin} wider each side}
     */
    boolean anyBehind(double x, double z, double heading, double radius, double margin, double reach, long nowMs) {
        forget(nowMs);
        return anyAhead(x, z, heading + Math.PI, radius, margin, reach);
    }

    private boolean anyAhead(double x, double z, double heading, double radius, double margin, double reach) {
        double c = Math.cos(heading), s = Math.sin(heading);
        for (Point p : points) {
            double dx = p.x() - x, dz = p.z() - z;
            double ahead = dx * c + dz * s, side = -dx * s + dz * c;
            if (Math.abs(side) >= radius + margin || ahead <= 0) {
                continue;
            }
            double rim = Math.sqrt(Math.max(0, radius * radius - side * side));
            if (ahead - rim < reach) {
                return true;
            }
        }
        return false;
    }
}
