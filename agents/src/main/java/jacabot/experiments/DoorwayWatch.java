package jacabot.experiments;

/**
 * A doorway beside a robot that drives along a wall (not in the thesis): one front sensor reads the
 * wall, then nothing (the doorway's gap), then the far jamb for a little while. The MyBot's sensors
 * look ±20° ahead, so the gap is seen before the robot is abreast of it; its middle lies
 * {@code lookahead} metres past the point where the gap began to be seen, less half the gap seen.
 * Used by {@link ObstacleAvoidanceMiddleware#doorwayWatch}; the distances are driven ones, from dead
 * reckoning, and the watch starts over whenever the robot stops going straight.
 */
final class DoorwayWatch {
    private final double level, before, after, flat, minGap, maxGap, lookahead;
    /**
     * Per side (0 left, 1 right): where the wall began to be seen, where the gap began, where the far
     * jamb began (NaN: not now), how long the gap was, and the far jamb's readings' range.
     */
    private final double[] wallFrom = new double[2], gapFrom = new double[2], jambFrom = new double[2], gap = new double[2],
            jambLow = new double[2], jambHigh = new double[2];
    private double driven, lastX = Double.NaN, lastZ;

    /**
     * @param level     a reading of this or more is a wall; under 1 is open floor
     * @param before    metres driven seeing the wall before the gap, at least
     * @param after     metres driven seeing the far jamb after it, at least
     * @param flat      the far jamb's readings over that stretch stay within this share of their greatest
     * @param minGap    the gap's least length seen, metres (a gap narrower than the robot shows less)
     * @param maxGap    its greatest (longer: the wall's end, not a doorway)
     * @param lookahead metres from where the gap began to be seen to its middle, for a robot beside the wall
     */
    DoorwayWatch(double level, double before, double after, double flat, double minGap, double maxGap, double lookahead) {
        this.level = level;
        this.before = before;
        this.after = after;
        this.flat = flat;
        this.minGap = minGap;
        this.maxGap = maxGap;
        this.lookahead = lookahead;
        reset();
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
            if (!Double.isNaN(jambFrom[k])) {
                found = jamb(k, r, found);
            } else if (!Double.isNaN(gapFrom[k])) {
                double g = driven - gapFrom[k];
                if (r >= level) {
                    gapFrom[k] = Double.NaN;
                    if (g >= minGap && g <= maxGap) {
                        jambFrom[k] = driven;
                        gap[k] = g;
                        jambLow[k] = r;
                        jambHigh[k] = r;
                    } else {
                        wallFrom[k] = driven;
                    }
                } else if (g > maxGap) {
                    gapFrom[k] = Double.NaN;
                }
            } else if (!Double.isNaN(wallFrom[k])) {
                if (r < 1) {
                    gapFrom[k] = driven - wallFrom[k] >= before ? driven : Double.NaN;
                    wallFrom[k] = Double.NaN;
                }
            } else if (r >= level) {
                wallFrom[k] = driven;
            }
        }
        return found;
    }

    /** The far jamb seen on side {@code k}: once seen for {@code after}, a doorway if its readings were steady. */
    private double[] jamb(int k, double r, double[] found) {
        if (r < level) {
            jambFrom[k] = Double.NaN;
            return found;
        }
        jambLow[k] = Math.min(jambLow[k], r);
        jambHigh[k] = Math.max(jambHigh[k], r);
        double since = driven - jambFrom[k];
        if (since < after) {
            return found;
        }
        jambFrom[k] = Double.NaN;
        wallFrom[k] = driven;
        double ahead = lookahead - gap[k] / 2 - since;
        return jambHigh[k] - jambLow[k] <= flat * jambHigh[k] && ahead > 0 ? new double[] {k, ahead} : found;
    }

    private void reset() {
        for (int k = 0; k < 2; k++) {
            wallFrom[k] = Double.NaN;
            gapFrom[k] = Double.NaN;
            jambFrom[k] = Double.NaN;
        }
        driven = 0;
        lastX = Double.NaN;
    }
}
