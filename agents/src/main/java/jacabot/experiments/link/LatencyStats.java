package jacabot.experiments.link;

import java.util.Arrays;
import java.util.Locale;

/**
 * A summary of latency samples in microseconds (thesis Chapter 5 §3: reactive time ≈ 2 ms,
 * response time ≈ 40 ms). All zero when there are no samples.
 */
public record LatencyStats(int count, long minMicros, double meanMicros, long medianMicros, long p90Micros, long p95Micros,
        long p99Micros, long maxMicros) {
    /** {@return the summary of some samples} */
    public static LatencyStats of(long[] samples) {
        if (samples.length == 0) {
            return new LatencyStats(0, 0, 0, 0, 0, 0, 0, 0);
        }
        long[] s = samples.clone();
        Arrays.sort(s);
        double sum = 0;
        for (long v : s) {
            sum += v;
        }
        return new LatencyStats(s.length, s[0], sum / s.length, s[(s.length - 1) / 2], percentile(s, 0.90),
                percentile(s, 0.95), percentile(s, 0.99), s[s.length - 1]);
    }

    /** The nearest-rank percentile of sorted samples. */
    private static long percentile(long[] sorted, double p) {
        return sorted[Math.max(0, (int) Math.ceil(p * sorted.length) - 1)];
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "n=%d mean=%.3f ms median=%.3f ms p90=%.3f ms p99=%.3f ms max=%.3f ms", count,
                meanMicros / 1000, medianMicros / 1000.0, p90Micros / 1000.0, p99Micros / 1000.0, maxMicros / 1000.0);
    }
}
