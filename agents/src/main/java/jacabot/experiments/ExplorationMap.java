package jacabot.experiments;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Where a robot without GPS has been (not in the thesis): its pose by dead reckoning from the wheel speeds
 * in effect, the 10 cm cells its centre has crossed, and the cells where it met an obstacle. It
 * proposes the turn towards the most floor not yet crossed, so that a random walk spreads over a
 * large arena instead of going over the same ground. The frame is the robot's start pose; the
 * heading grows with left turns (right wheel faster).
 */
final class ExplorationMap {
    static final double CELL = 0.10;
    /** How far ahead a candidate heading is scored by default, metres. */
    static final double HORIZON = 3.0;
    /** Candidate headings: every 30 degrees around. */
    static final int DIRECTIONS = 12;

    private final double speedUnit, axle;
    private double horizon = HORIZON;
    private double x, z, heading; // metres, metres, radians
    private double left, right;   // wheel speeds in effect, speed units
    private long lastMs = -1;
    private long lastFreshMs; // when the centre last entered a cell not crossed before
    private final Set<Long> visited = new HashSet<>();
    private final Set<Long> blocked = new HashSet<>();
    private final Deque<Long> freshTimes = new ArrayDeque<>(); // when each cell was first crossed, oldest first

    /**
     * @param speedUnit metres per second of one wheel speed unit
     * @param axle      distance between the wheels, metres
     */
    ExplorationMap(double speedUnit, double axle) {
        if (!(speedUnit > 0) || !(axle > 0)) {
            throw new IllegalArgumentException("speed unit and axle length must be positive, got " + speedUnit + ", " + axle);
        }
        this.speedUnit = speedUnit;
        this.axle = axle;
        visit();
    }

    /** Scores headings over {@code metres} ahead from now on. */
    void horizon(double metres) {
        if (!(metres >= CELL)) {
            throw new IllegalArgumentException("horizon must be at least " + CELL + " m, got " + metres);
        }
        horizon = metres;
    }

    /** The wheel speeds in effect from {@code nowMs} on: the motion since the last call is integrated first. */
    void wheels(long nowMs, double newLeft, double newRight) {
        if (lastMs >= 0 && nowMs > lastMs) {
            double dt = (nowMs - lastMs) / 1000.0;
            double vl = left * speedUnit, vr = right * speedUnit;
            double v = (vl + vr) / 2, w = (vr - vl) / axle;
            double mid = heading + w * dt / 2;
            x += v * Math.cos(mid) * dt;
            z += v * Math.sin(mid) * dt;
            heading += w * dt;
            if (visit()) {
                lastFreshMs = nowMs;
                freshTimes.addLast(nowMs);
            }
        }
        lastMs = nowMs;
        left = newLeft;
        right = newRight;
    }

    /** An obstacle {@code distance} metres from the centre, {@code bearing} degrees left of the heading. */
    void obstacle(double bearing, double distance) {
        double a = heading + Math.toRadians(bearing);
        blocked.add(key(x + distance * Math.cos(a), z + distance * Math.sin(a)));
    }

    /** {@return the turn in degrees (positive: left) towards the most cells not yet crossed, small turns first on a tie} */
    double bestTurn() {
        double best = 0, bestScore = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < DIRECTIONS; k++) {
            double turn = k <= DIRECTIONS / 2 ? k * 360.0 / DIRECTIONS : (k - DIRECTIONS) * 360.0 / DIRECTIONS;
            double score = score(heading + Math.toRadians(turn)) - Math.abs(turn) / 360.0;
            if (score > bestScore) {
                bestScore = score;
                best = turn;
            }
        }
        return best;
    }

    private double score(double a) {
        int fresh = 0;
        long previous = key(x, z);
        for (double d = CELL / 2; d <= horizon + 1e-9; d += CELL / 2) {
            long k = key(x + d * Math.cos(a), z + d * Math.sin(a));
            if (blocked.contains(k)) {
                break;
            }
            if (k != previous && !visited.contains(k)) {
                fresh++;
            }
            previous = k;
        }
        return fresh;
    }

    private boolean visit() {
        return visited.add(key(x, z));
    }

    /** {@return how long, up to {@code nowMs}, the centre has crossed only cells crossed before, in ms} */
    long staleMillis(long nowMs) {
        return Math.max(0, nowMs - lastFreshMs);
    }

    /** How far past a frontier cell the floor must be open (not crossed, no obstacle met), cells. */
    static final int OPEN_DEPTH = 3;
    /** How far along the path to a frontier the next waypoint lies, cells. */
    static final int WAYPOINT = 4;

    /**
     * The way to the nearest frontier (not in the thesis): the nearest cell not crossed yet, reached
     * through crossed cells only, which and {@value #OPEN_DEPTH} more cells straight on beyond it are
     * not crossed and have no obstacle met in them or beside them across the way: a doorway out of a
     * covered room (two cells wide at least), not the margin along its walls, where obstacles were met. {@return {turn in degrees, left positive; distance in metres} to a waypoint up to
     * {@value #WAYPOINT} cells along that way, or null when there is none}
     */
    double[] frontierWaypoint() {
        long start = key(x, z);
        Map<Long, Long> parent = new HashMap<>();
        Deque<Long> queue = new ArrayDeque<>();
        parent.put(start, start);
        queue.add(start);
        int[][] steps = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        while (!queue.isEmpty()) {
            long k = queue.poll();
            int i = (int) (k >> 32), j = (int) k;
            for (int[] d : steps) {
                long n = key(i + d[0], j + d[1]);
                if (parent.containsKey(n) || blocked.contains(n)) {
                    continue;
                }
                parent.put(n, k);
                if (visited.contains(n)) {
                    queue.add(n);
                } else if (openBeyond(i + d[0], j + d[1], d)) {
                    return waypoint(parent, n, start);
                }
            }
        }
        return null;
    }

    private boolean openBeyond(int i, int j, int[] d) {
        for (int s = 0; s <= OPEN_DEPTH; s++) {
            int a = i + s * d[0], b = j + s * d[1];
            if ((s > 0 && visited.contains(key(a, b))) || blocked.contains(key(a, b))
                    || blocked.contains(key(a + d[1], b + d[0])) || blocked.contains(key(a - d[1], b - d[0]))) {
                return false;
            }
        }
        return true;
    }

    private double[] waypoint(Map<Long, Long> parent, long target, long start) {
        List<Long> path = new ArrayList<>();
        for (long k = target; k != start; k = parent.get(k)) {
            path.add(0, k);
        }
        long w = path.get(Math.min(WAYPOINT, path.size()) - 1);
        double wx = ((int) (w >> 32) + 0.5) * CELL, wz = ((int) w + 0.5) * CELL;
        double turn = Math.toDegrees(Math.atan2(wz - z, wx - x) - heading);
        turn = ((turn % 360) + 540) % 360 - 180;
        return new double[] {turn, Math.hypot(wx - x, wz - z)};
    }

    /** {@return how many cells the centre crossed for the first time after {@code sinceMs}} */
    int freshCellsSince(long sinceMs) {
        int n = 0;
        for (var it = freshTimes.descendingIterator(); it.hasNext() && it.next() > sinceMs; ) {
            n++;
        }
        return n;
    }

    /** {@return how long a turn of {@code degrees} on the spot takes, wheels at ±{@code wheelSpeed}, in ms} */
    long turnMillis(double degrees, double wheelSpeed) {
        double degreesPerSecond = Math.toDegrees(2 * wheelSpeed * speedUnit / axle);
        return Math.round(1000 * Math.abs(degrees) / degreesPerSecond);
    }

    int cellsVisited() {
        return visited.size();
    }

    double x() {
        return x;
    }

    double z() {
        return z;
    }

    /** {@return the heading in degrees, left turns positive} */
    double headingDegrees() {
        return Math.toDegrees(heading);
    }

    private static long key(double px, double pz) {
        return key((int) Math.floor(px / CELL), (int) Math.floor(pz / CELL));
    }

    private static long key(int i, int j) {
        return ((long) i << 32) ^ (j & 0xFFFFFFFFL);
    }
}
