package jacabot.sim.engine;

/**
 * Each ray bearing's radians, cosine, sine and unit direction, kept by the bearing's bits: the
 * same bearing gives the same bits, so the rays are those formed afresh, to the bit. Why: a
 * camera's 64 columns keep their bearings from one frame to the next whenever the robot's heading
 * does (about half the frames of a suspend-resume run: the robot driving straight or standing),
 * and a cosine and a sine cost about as much as the rest of a column's broad phase. A table of
 * one entry per slot, the slot picked by the bits, in flat arrays (no object per entry). Like the
 * world it serves, not thread-safe: rays are cast on the thread that steps the world. Internal to
 * sim-world.
 */
final class BeamDirections {
    /** Slots: a power of two, several times the rays a world's robots cast in a step. */
    private static final int SLOT_BITS = 10;
    private static final int SLOTS = 1 << SLOT_BITS;
    /** What a slot keeps, after the bearing's bits. */
    static final int RADIANS = 0, COS = 1, SIN = 2, DX = 3, DY = 4, WIDTH = 5;

    private final long[] bearings = new long[SLOTS];
    private final boolean[] filled = new boolean[SLOTS];
    private final double[] values = new double[SLOTS * WIDTH];

    /**
     * {@return where a bearing's (degrees) values start in {@link #values()}}: the kept ones, or ones
     * formed as dyn4j's {@code Ray} forms its direction (cosine and sine, then normalised) and kept
     */
    int of(double bearingDeg) {
        long bits = Double.doubleToRawLongBits(bearingDeg);
        int slot = (int) ((bits ^ bits >>> 32) * 0x9E3779B97F4A7C15L >>> (64 - SLOT_BITS));
        int at = slot * WIDTH;
        if (!filled[slot] || bearings[slot] != bits) {
            double r = Math.toRadians(bearingDeg);
            double c = Math.cos(r), s = Math.sin(r);
            double inverse = 1.0 / Math.sqrt(c * c + s * s);
            values[at + RADIANS] = r;
            values[at + COS] = c;
            values[at + SIN] = s;
            values[at + DX] = c * inverse;
            values[at + DY] = s * inverse;
            bearings[slot] = bits;
            filled[slot] = true;
        }
        return at;
    }

    /** {@return the table {@link #of} points into} */
    double[] values() {
        return values;
    }
}
