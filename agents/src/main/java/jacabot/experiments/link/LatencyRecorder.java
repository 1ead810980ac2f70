package jacabot.experiments.link;

/** The last {@code capacity} samples of one latency, thread-safe; a ring so a long run stays bounded. */
public final class LatencyRecorder {
    private final long[] ring;
    private int next, size;

    public LatencyRecorder(int capacity) {
        this.ring = new long[capacity];
    }

    /** Records one sample; negative ones (clock adjustments) are dropped. */
    public synchronized void record(long micros) {
        if (micros < 0) {
            return;
        }
        ring[next] = micros;
        next = (next + 1) % ring.length;
        size = Math.min(size + 1, ring.length);
    }

    /** Forgets every sample so far (the end of a warm-up). */
    public synchronized void clear() {
        next = 0;
        size = 0;
    }

    public synchronized LatencyStats stats() {
        return LatencyStats.of(samples());
    }

    /** {@return the samples kept, oldest first (e.g. for a histogram)} */
    public synchronized long[] samples() {
        long[] s = new long[size];
        for (int i = 0; i < size; i++) {
            s[i] = ring[(next - size + i + ring.length) % ring.length];
        }
        return s;
    }
}
