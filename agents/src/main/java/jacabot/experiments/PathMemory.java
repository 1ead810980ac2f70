package jacabot.experiments;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The points where the front sensors met a wall or box in the last few seconds, on the dead-reckoning
 * map's frame (not in the thesis). The MyBot's two sensors look 20° off its heading: a box they saw
 * while the robot turned away from it is out of their sight well before it is out of the robot's way,
 * and the straight leg after the turn slid the robot's flank along it. This memory tells whether
 * such a point still lies in the strip the robot's body sweeps when it drives straight on.
 */
final class PathMemory {
    private final long keepMs;
    private final Deque<double[]> points = new ArrayDeque<>(); // {time ms, x, z}

    PathMemory(long keepMs) {
        this.keepMs = keepMs;
    }

    /** Remembers a point met at {@code nowMs}, forgetting those older than the memory's span. */
    void add(long nowMs, double x, double z) {
        forget(nowMs);
        points.addLast(new double[] {nowMs, x, z});
    }

    private void forget(long nowMs) {
        while (!points.isEmpty() && points.peekFirst()[0] < nowMs - keepMs) {
            points.removeFirst();
        }
    }

    /**
     * {@return whether a remembered point lies ahead of a robot at (x, z) heading {@code headingDeg}
     * (left turns positive), less than {@code length} metres along its heading and less than
     * {@code halfWidth} metres off its centre line}
     */
    boolean inPath(long nowMs, double x, double z, double headingDeg, double halfWidth, double length) {
        forget(nowMs);
        double c = Math.cos(Math.toRadians(headingDeg)), s = Math.sin(Math.toRadians(headingDeg));
        for (double[] p : points) {
            double dx = p[1] - x, dz = p[2] - z;
            double along = dx * c + dz * s, across = -dx * s + dz * c;
            if (along > 0 && along < length && Math.abs(across) < halfWidth) {
                return true;
            }
        }
        return false;
    }
}
