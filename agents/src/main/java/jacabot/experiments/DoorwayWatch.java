package jacabot.experiments;

/**
 * A doorway beside a robot that drives along a wall (not in the thesis): one front sensor reads the
 * wall for a while, then nothing (the doorway's gap), then the wall again. The MyBot's sensors look
 * ±20° ahead, so the gap is seen before the robot is abreast of it; its middle lies
 * {@code lookahead} metres past the point where the gap began to be seen, less half the gap seen.
 * Used by {@link ObstacleAvoidanceMiddleware#doorwayWatch}; the distances are driven ones, from dead
 * reckoning, and the watch starts over whenever the robot stops going straight.
 */
final class DoorwayWatch {
    private final double level, wallSpan, minGap, maxGap, lookahead;
    /** Per side (0 left, 1 right): where the wall began to be seen, where the gap began (NaN: not now). */
    private final double[] wallFrom = {Double.NaN, Double.NaN}, gapFrom = {Double.NaN, Double.NaN};
    /** Per side: whether the wall before the gap was seen for wallSpan or more. */
    private final boolean[] longWall = new boolean[2];
    private double driven, lastX = Double.NaN, lastZ;

    /**
     * @param level     a reading of this or more is the wall; under 1 is open floor
     * @param wallSpan  metres driven seeing the wall before the gap, at least (a box is shorter)
     * @param minGap    the gap's least length seen, metres (a gap narrower than the robot shows less)
     * @param maxGap    its greatest (longer: the wall's end, not a doorway)
     * @param lookahead metres from where the gap began to be seen to its middle, for a robot beside the wall
     */
    DoorwayWatch(double level, double wallSpan, double minGap, double maxGap, double lookahead) {
        this.level = level;
        this.wallSpan = wallSpan;
        this.minGap = minGap;
        this.maxGap = maxGap;
        this.lookahead = lookahead;
    }

    /**
     * Takes a pair of readings at the robot's dead-reckoning position.
     *
     * @return {side (0 left, 1 right), metres still to drive to be abreast of the doorway's middle},
     *     or null when no doorway was just seen
     */
    double[] update(double x, double z, boolean straight, double left, double right) {
        if (!straight || Double.isNaN(lastX)) {
            reset();
            lastX = x;
            lastZ = z;
            return null;
        }
        driven += Math.hypot(x - lastX, z - lastZ);
        lastX = x;
        lastZ = z;
        double[] found = null;
        for (int k = 0; k < 2; k++) {
            double r = k == 0 ? left : right;
            if (r >= level) {
                if (!Double.isNaN(gapFrom[k])) {
                    double gap = driven - gapFrom[k];
                    double ahead = lookahead - gap / 2;
                    if (longWall[k] && gap >= minGap && gap <= maxGap && ahead > 0) {
                        found = new double[] {k, ahead};
                    }
                    gapFrom[k] = Double.NaN;
                    wallFrom[k] = driven;
                } else if (Double.isNaN(wallFrom[k])) {
                    wallFrom[k] = driven;
                }
            } else if (r < 1) {
                if (!Double.isNaN(wallFrom[k])) {
                    longWall[k] = driven - wallFrom[k] >= wallSpan;
                    gapFrom[k] = driven;
                    wallFrom[k] = Double.NaN;
                } else if (!Double.isNaN(gapFrom[k]) && driven - gapFrom[k] > maxGap) {
                    gapFrom[k] = Double.NaN;
                }
            }
        }
        return found;
    }

    private void reset() {
        for (int k = 0; k < 2; k++) {
            wallFrom[k] = Double.NaN;
            gapFrom[k] = Double.NaN;
            longWall[k] = false;
        }
        driven = 0;
        lastX = Double.NaN;
    }
}
