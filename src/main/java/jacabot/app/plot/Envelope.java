package jacabot.app.plot;

import java.util.ArrayList;
import java.util.List;

/**
 * A time series thinned to what a chart of a given width can show: the steps split into as many
 * equal runs as the chart has columns, and of each run its first and last points and its lowest
 * and highest values, in time order. A plot of the envelope looks like a plot of every point (each
 * column still reaches from the run's lowest to its highest value), and a 10-minute run's 15 000
 * steps become at most four points a column.
 *
 * <p>Why: XChart finds the ticks of an X axis whose values are equally spaced (every control step)
 * by formatting and measuring every value again for each candidate spacing, which took most of a
 * run's plotting time; the envelope has few points, not equally spaced once a value moves.
 */
final class Envelope {
    final List<Double> x = new ArrayList<>();
    final List<Double> y = new ArrayList<>();

    private Envelope() {
    }

    /** {@return the envelope of the points (x[i], y[i]), at most four points for each of {@code columns}} */
    static Envelope of(List<Double> xs, List<Double> ys, int columns) {
        Envelope e = new Envelope();
        int n = Math.min(xs.size(), ys.size());
        if (n <= 4 * columns) {
            e.x.addAll(xs.subList(0, n));
            e.y.addAll(ys.subList(0, n));
            return e;
        }
        for (int c = 0; c < columns; c++) {
            int from = (int) ((long) n * c / columns), to = (int) ((long) n * (c + 1) / columns); // [from, to), never empty
            int low = -1, high = -1;
            for (int i = from; i < to; i++) {
                double v = ys.get(i);
                if (!Double.isNaN(v)) {
                    low = low < 0 || v < ys.get(low) ? i : low;
                    high = high < 0 || v > ys.get(high) ? i : high;
                }
            }
            int last = to - 1;
            int[] picked = {from, Math.min(low < 0 ? from : low, high < 0 ? from : high),
                    Math.max(low < 0 ? from : low, high < 0 ? from : high), last};
            int previous = -1;
            for (int i : picked) {
                if (i != previous) { // in time order, each point once
                    e.x.add(xs.get(i));
                    e.y.add(ys.get(i));
                    previous = i;
                }
            }
        }
        return e;
    }
}
