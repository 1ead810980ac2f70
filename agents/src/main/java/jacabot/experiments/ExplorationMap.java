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
    /**
     * The obstacle marks' cells, metres a side: a quarter of a floor cell. A mark blocks every such
     * cell within {@value #MARK_RADIUS} m of where the wall or box was read, the floor the robot's
     * centre cannot reach there; with the marks on the 10 cm floor cells, a cell holding a jamb of
     * a passage 12-17 cm wide (the robot 9 cm across) also held most of the gap.
     */
    static final double MARK_CELL = CELL / 4;
    /** How far from a wall or box read the robot's centre is kept, metres: the robot's radius (4.5 cm) and 1.5 cm. */
    static final double MARK_RADIUS = 0.06;
    /** The mark cells whose centre lies this close to the robot's centre hold no wall: the robot stood there. */
    static final double SWEPT = MARK_CELL;

    private final double speedUnit, axle;
    private double horizon = HORIZON;
    private double x, z, heading; // metres, metres, radians
    private double left, right;   // wheel speeds in effect, speed units
    private long lastMs = -1;
    private long lastFreshMs; // when the centre last entered a cell not crossed before
    private final Set<Long> visited = new HashSet<>();
    private final Set<Long> blocked = new HashSet<>(); // mark cells (MARK_CELL)
    private final Set<Long> swept = new HashSet<>();   // mark cells the robot's centre passed over
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
        sweep();
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
            sweep();
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
        for (long k : markCellsNear(x + distance * Math.cos(a), z + distance * Math.sin(a), MARK_RADIUS)) {
            if (!swept.contains(k)) {
                blocked.add(k);
            }
        }
    }

    /** {@return the mark cells whose centre lies within {@code radius} m of (px, pz)} */
    private static List<Long> markCellsNear(double px, double pz, double radius) {
        List<Long> cells = new ArrayList<>();
        int i0 = (int) Math.floor((px - radius) / MARK_CELL), i1 = (int) Math.floor((px + radius) / MARK_CELL);
        int j0 = (int) Math.floor((pz - radius) / MARK_CELL), j1 = (int) Math.floor((pz + radius) / MARK_CELL);
        for (int i = i0; i <= i1; i++) {
            for (int j = j0; j <= j1; j++) {
                if (Math.hypot((i + 0.5) * MARK_CELL - px, (j + 0.5) * MARK_CELL - pz) <= radius) {
                    cells.add(key(i, j));
                }
            }
        }
        return cells;
    }

    /** The mark cells under the robot's centre (within {@value #SWEPT} m) lose their marks and take no more. */
    private void sweep() {
        for (long k : markCellsNear(x, z, SWEPT)) {
            swept.add(k);
            blocked.remove(k);
        }
    }

    /** {@return whether any mark cell of floor cell (i, j) holds an obstacle mark} */
    private boolean blockedCell(int i, int j) {
        int n = (int) Math.round(CELL / MARK_CELL);
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                if (blocked.contains(key(i * n + a, j * n + b))) {
                    return true;
                }
            }
        }
        return false;
    }

    private boolean blockedCell(long k) {
        return blockedCell((int) (k >> 32), (int) k);
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
        // the floor is read every half cell as before; the marks every quarter mark cell between, so
        // that a line of marks touching only at their corners still stops the ray
        int perSample = (int) Math.round(CELL / 2 / (MARK_CELL / 4));
        for (int n = 1; n * (MARK_CELL / 4) <= horizon + 1e-9; n++) {
            double d = n * (MARK_CELL / 4), px = x + d * Math.cos(a), pz = z + d * Math.sin(a);
            if (blocked.contains(markKey(px, pz))) {
                break;
            }
            if (n % perSample != 0) {
                continue;
            }
            long k = key(px, pz);
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
                if (parent.containsKey(n) || blockedCell(n)) {
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
            if ((s > 0 && visited.contains(key(a, b))) || blockedCell(a, b)
                    || blockedCell(a + d[1], b + d[0]) || blockedCell(a - d[1], b - d[0])) {
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

    private static long markKey(double px, double pz) {
        return key((int) Math.floor(px / MARK_CELL), (int) Math.floor(pz / MARK_CELL));
    }

    private static long key(int i, int j) {
        return ((long) i << 32) ^ (j & 0xFFFFFFFFL);
    }
}
