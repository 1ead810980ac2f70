package jacabot.experiments;

/**
 * The front readings' shape at a passage's mouth met head-on (not in the thesis): the sensor that
 * looks into the passage reads its side wall at a steady level, while the other, on the jamb's
 * face, climbs as the robot drives on; the weaker reading settled only just before (its ray has
 * just gone into the passage). A box met off-centre leaves the weaker sensor at nothing, a plain
 * wall met head-on makes both climb, and a wall beside the robot, read steadily for long, is no mouth.
 */
final class MouthShape {
    private final double low, flat, rise, moved, fall;
    private final int steps;
    /** The last two windows' readings and poses: left, right, x, z. */
    private final double[][] ring;
    private int count;

    /**
     * @param low the weaker reading's least level
     * @param flat how far the weaker reading may have moved over the window
     * @param rise how much the stronger reading must have climbed over it
     * @param steps the window, in reading pairs (40 ms each); a window earlier the weaker reading was
     *     more than {@code flat} off its level now
     * @param moved how far the robot must have driven over it, metres (not a turn on the spot)
     */
    MouthShape(double low, double flat, double rise, int steps, double moved) {
        this(low, flat, rise, steps, moved, 0);
    }

    /** As above, and also a mouth where the weaker reading fell by {@code fall} over the window (0: not). */
    MouthShape(double low, double flat, double rise, int steps, double moved, double fall) {
        this.fall = fall;
        this.low = low;
        this.flat = flat;
        this.rise = rise;
        this.steps = steps;
        this.moved = moved;
        ring = new double[2 * steps + 1][];
    }

    /** {@return whether the pair just read, at pose (x, z), ends a mouth's shape} */
    boolean read(double left, double right, double x, double z) {
        ring[count % ring.length] = new double[] {left, right, x, z};
        count++;
        if (count < ring.length) {
            return false;
        }
        double[] before = ring[count % ring.length], first = ring[(count + steps) % ring.length];
        boolean leftLow = left < right;
        int weak = leftLow ? 0 : 1, strong = 1 - weak;
        double now = leftLow ? left : right;
        if ((leftLow ? right : left) - first[strong] < rise || Math.hypot(x - first[2], z - first[3]) < moved) {
            return false;
        }
        if (fall > 0 && first[weak] - now >= fall) {
            return true; // the weaker ray leaves the jamb's face for the passage while the other climbs
        }
        if (now < low || Math.abs(before[weak] - now) <= flat) {
            return false;
        }
        for (int k = 0; k <= steps; k++) {
            if (Math.abs(ring[(count + steps + k) % ring.length][weak] - now) > flat) {
                return false;
            }
        }
        return true;
    }
}
