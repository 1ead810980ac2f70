package jacabot.experiments;

import java.util.HashSet;
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
        long i = (long) Math.floor(px / CELL), j = (long) Math.floor(pz / CELL);
        return (i << 32) ^ (j & 0xFFFFFFFFL);
    }
}
