package jacabot.experiments;

/**
 * The front readings' shape at a passage's mouth met head-on (not in the thesis): the sensor that
 * looks into the passage reads its side wall at a steady level, while the other, on the jamb's
 * face, climbs as the robot drives on. A box met off-centre leaves the weaker sensor at nothing,
 * and a plain wall met head-on makes both climb.
 */
final class MouthShape {
    private final double low, flat, rise, moved;
    private final int steps;
    /** The last readings and poses, oldest first once full: left, right, x, z. */
    private final double[][] ring;
    private int count;

    /**
     * @param low the weaker reading's least level
     * @param flat how far the weaker reading may have moved over the window
     * @param rise how much the stronger reading must have climbed over it
     * @param steps the window, in reading pairs (40 ms each)
     * @param moved how far the robot must have driven over it, metres (not a turn on the spot)
     */
    MouthShape(double low, double flat, double rise, int steps, double moved) {
        this.low = low;
        this.flat = flat;
        this.rise = rise;
        this.steps = steps;
        this.moved = moved;
        ring = new double[steps + 1][];
    }

    /** {@return whether the pair just read, at pose (x, z), ends a mouth's shape} */
    boolean read(double left, double right, double x, double z) {
        ring[count % ring.length] = new double[] {left, right, x, z};
        count++;
        if (count < ring.length) {
            return false;
        }
        double[] first = ring[count % ring.length];
        boolean leftLow = left < right;
        int weak = leftLow ? 0 : 1, strong = 1 - weak;
        double now = leftLow ? left : right;
        if (now < low || (leftLow ? right : left) - first[strong] < rise || Math.hypot(x - first[2], z - first[3]) < moved) {
            return false;
        }
        for (double[] pair : ring) {
            if (Math.abs(pair[weak] - now) > flat) {
                return false;
            }
        }
        return true;
    }
}
