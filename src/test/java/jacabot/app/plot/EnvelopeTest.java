package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** A thinned series keeps every column's extremes and its ends, in time order, at most four points a column. */
class EnvelopeTest {
    @Test
    void keepsEachColumnsLowestHighestFirstAndLast() {
        Random rnd = new Random(4);
        int n = 15_000;
        double[] t = new double[n], y = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.04;
            y[i] = rnd.nextInt(50) == 0 ? rnd.nextGaussian() * 100 : Math.sin(i / 300.0); // rare spikes
        }
        int columns = 900;
        Envelope e = Envelope.of(t, y, columns);
        assertTrue(e.x().length <= 4 * columns && e.x().length >= 2 * columns, "points " + e.x().length);
        for (int i = 1; i < e.x().length; i++) {
            assertTrue(e.x()[i] > e.x()[i - 1], "time order at " + i);
        }
        for (int c = 0; c < columns; c++) {
            int from = n * c / columns, to = n * (c + 1) / columns;
            double low = Double.MAX_VALUE, high = -Double.MAX_VALUE;
            for (int i = from; i < to; i++) {
                low = Math.min(low, y[i]);
                high = Math.max(high, y[i]);
            }
            double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
            boolean first = false, last = false;
            for (int k = 0; k < e.x().length; k++) {
                if (e.x()[k] >= t[from] && e.x()[k] <= t[to - 1]) {
                    lo = Math.min(lo, e.y()[k]);
                    hi = Math.max(hi, e.y()[k]);
                }
                first |= e.x()[k] == t[from];
                last |= e.x()[k] == t[to - 1];
            }
            assertEquals(low, lo, 0.0, "column " + c);
            assertEquals(high, hi, 0.0, "column " + c);
            assertTrue(first && last, "column " + c + "'s ends");
        }
    }

    @Test
    void aShortSeriesIsKeptWholeAndGapsStay() {
        double[] t = {0.0, 1.0, 2.0}, y = {1.0, Double.NaN, 3.0};
        Envelope e = Envelope.of(t, y, 900);
        assertArrayEquals(t, e.x());
        assertArrayEquals(y, e.y());
        double[] lt = new double[100], ly = new double[100];
        for (int i = 0; i < 100; i++) {
            lt[i] = i;
            ly[i] = Double.NaN;
        }
        Envelope nan = Envelope.of(lt, ly, 10);
        assertTrue(Arrays.stream(nan.y()).allMatch(Double::isNaN) && nan.x().length == 20,
                "a column without values keeps its ends: " + Arrays.toString(nan.x()));
    }
}
