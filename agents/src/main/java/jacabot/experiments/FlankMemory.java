package jacabot.experiments;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The points where the front sensors met a wall or box in the last moments, on the dead-reckoning
 * frame, and how sharply the robot must bend away from those that lie in the strip its body sweeps
 * just ahead (not in the thesis). The MyBot's sensors look 20° off its heading: a box they saw while
 * the robot turned away from it leaves their sight before it leaves the robot's way, and the straight
 * leg after the turn slid the flank along it.
 */
final class FlankMemory {
    private final long keepMs;
    private final double reach, clearReach, length;
    private final Deque<double[]> points = new ArrayDeque<>(); // {time ms, x, z, 1 if met while avoiding else 0}

    /**
     * @param keepMs how long a point is remembered
     * @param reach  how far off the centre line a point counts, metres (the body's radius and a margin)
     * @param clearReach how far off the centre line the side bent towards must be free of points, metres
     * @param length how far ahead of the centre a point counts, metres
     */
    FlankMemory(long keepMs, double reach, double clearReach, double length) {
        this.keepMs = keepMs;
        this.reach = reach;
        this.clearReach = clearReach;
        this.length = length;
    }

    /** Remembers a point met at {@code nowMs} (while avoiding an obstacle or not), forgetting those older than the memory's span. */
    void add(long nowMs, double x, double z, boolean avoiding) {
        forget(nowMs);
        points.addLast(new double[] {nowMs, x, z, avoiding ? 1 : 0});
    }

    private void forget(long nowMs) {
        while (!points.isEmpty() && points.peekFirst()[0] < nowMs - keepMs) {
            points.removeFirst();
        }
    }

    /**
     * {@return the curvature (1/m, positive: bend right) that takes a robot at (x, z) heading
     * {@code headingDeg} (left turns positive) clear of the points met while avoiding that lie in its
     * strip}: for a point {@code along} ahead and {@code across} off the centre line, an arc of
     * curvature k moves the centre k·along²/2 sideways by the time it is level with the point, which
     * must make up {@code reach - |across|}; the sharpest point on each side counts, and the two sides
     * offset each other. No bend towards a side with any point (met while avoiding or not) within
     * {@code clearReach} beside or ahead: a bend away from one box drove the flank into another, seen
     * less closely. Points closer ahead than a centimetre count as a centimetre ahead.
     */
    double bend(long nowMs, double x, double z, double headingDeg) {
        forget(nowMs);
        double c = Math.cos(Math.toRadians(headingDeg)), s = Math.sin(Math.toRadians(headingDeg));
        double left = 0, right = 0;
        boolean leftSeen = false, rightSeen = false;
        for (double[] p : points) {
            double dx = p[1] - x, dz = p[2] - z;
            double along = dx * c + dz * s, across = -dx * s + dz * c;
            if (along < -reach || along > length || Math.abs(across) >= clearReach) {
                continue;
            }
            leftSeen |= across > 0;
            rightSeen |= across <= 0;
            if (p[3] == 0 || along < 0 || Math.abs(across) >= reach) {
                continue;
            }
            double a = Math.max(along, 0.01);
            double k = 2 * (reach - Math.abs(across)) / (a * a);
            if (across > 0) {
                left = Math.max(left, k);
            } else {
                right = Math.max(right, k);
            }
        }
        double k = left - right;
        return k > 0 && rightSeen || k < 0 && leftSeen ? 0 : k;
    }
}
