package jacabot.experiments;

/**
 * A robot pinned while it drives forward (not in the thesis): both front sensors hold the same high
 * reading for a while. Driving on, the readings would climb; steady, the robot pushes against
 * something between the two rays (a thin wall's end) or pushes a box along, and dead reckoning,
 * which counts the wheels, believes it crosses new floor.
 */
final class PinnedWatch {
    private final double level, diff, flat;
    private final long holdMs;
    /** When the readings began to hold steady, and their levels then; -1: not holding. */
    private long since = -1;
    private double left0, right0;

    /**
     * @param level both readings' least level
     * @param diff the largest left-right difference
     * @param flat how far each reading may move from its level when the hold began
     * @param holdMs how long they must hold
     */
    PinnedWatch(double level, double diff, double flat, long holdMs) {
        this.level = level;
        this.diff = diff;
        this.flat = flat;
        this.holdMs = holdMs;
    }

    /** {@return whether the robot is pinned, given the pair read at {@code timeMs} and whether it drives forward} */
    boolean read(double left, double right, boolean forward, long timeMs) {
        boolean steady = forward && left >= level && right >= level && Math.abs(left - right) <= diff;
        if (steady && since >= 0 && Math.abs(left - left0) <= flat && Math.abs(right - right0) <= flat) {
            return timeMs - since >= holdMs;
        }
        since = steady ? timeMs : -1;
        left0 = left;
        right0 = right;
        return false;
    }
}
