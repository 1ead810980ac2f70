package jacabot.app.plot;

import java.util.Arrays;

/**
 * A time series thinned to what a chart of a given width can show: the steps split into as many
 * equal runs as the chart has columns, and of each run its first and last points and its lowest
 * and highest values, in time order. A plot of the envelope looks like a plot of every point (each
 * column still reaches from the run's lowest to its highest value), and a 10-minute run's 15 000
 * steps become at most four points a column.
 *
 * <p>Why: XChart finds the ticks of an X axis whose values are equally spaced (every control step)
 * by formatting and measuring every value again for each candidate spacing, which took most of a
 * run's plotting time; the envelope has few points, not equally spaced once a column has more than
 * four steps.
 */
record Envelope(double[] x, double[] y) {
    /** {@return the envelope of the points (xs[i], ys[i]), at most four points for each of {@code columns}} */
    static Envelope of(double[] xs, double[] ys, int columns) {
        int n = Math.min(xs.length, ys.length);
        if (n <= 4 * columns) {
            return new Envelope(Arrays.copyOf(xs, n), Arrays.copyOf(ys, n));
        }
        double[] ex = new double[4 * columns], ey = new double[4 * columns];
        int size = 0;
        for (int c = 0; c < columns; c++) {
            int from = (int) ((long) n * c / columns), to = (int) ((long) n * (c + 1) / columns); // [from, to), never empty
            int low = -1, high = -1;
            for (int i = from; i < to; i++) {
                double v = ys[i];
                if (!Double.isNaN(v)) {
                    low = low < 0 || v < ys[low] ? i : low;
                    high = high < 0 || v > ys[high] ? i : high;
                }
            }
            low = low < 0 ? from : low;
            high = high < 0 ? from : high;
            int previous = -1;
            for (int i : new int[] {from, Math.min(low, high), Math.max(low, high), to - 1}) {
                if (i != previous) { // in time order, each point once
                    ex[size] = xs[i];
                    ey[size] = ys[i];
                    size++;
                    previous = i;
                }
            }
        }
        return new Envelope(Arrays.copyOf(ex, size), Arrays.copyOf(ey, size));
    }
}
