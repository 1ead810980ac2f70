package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** A thinned series keeps every column's extremes and its ends, in time order, at most four points a column. */
class EnvelopeTest {
    @Test
    void keepsEachColumnsLowestHighestFirstAndLast() {
        Random rnd = new Random(4);
        List<Double> t = new ArrayList<>(), y = new ArrayList<>();
        for (int i = 0; i < 15_000; i++) {
            t.add(i * 0.04);
            y.add(rnd.nextInt(50) == 0 ? rnd.nextGaussian() * 100 : Math.sin(i / 300.0)); // rare spikes
        }
        int columns = 900;
        Envelope e = Envelope.of(t, y, columns);
        assertTrue(e.x.size() <= 4 * columns && e.x.size() >= 2 * columns, "points " + e.x.size());
        for (int i = 1; i < e.x.size(); i++) {
            assertTrue(e.x.get(i) > e.x.get(i - 1), "time order at " + i);
        }
        for (int c = 0; c < columns; c++) {
            int from = 15_000 * c / columns, to = 15_000 * (c + 1) / columns;
            double low = Double.MAX_VALUE, high = -Double.MAX_VALUE;
            for (int i = from; i < to; i++) {
                low = Math.min(low, y.get(i));
                high = Math.max(high, y.get(i));
            }
            double lo = Double.MAX_VALUE, hi = -Double.MAX_VALUE;
            for (int k = 0; k < e.x.size(); k++) {
                if (e.x.get(k) >= t.get(from) && e.x.get(k) <= t.get(to - 1)) {
                    lo = Math.min(lo, e.y.get(k));
                    hi = Math.max(hi, e.y.get(k));
                }
            }
            assertEquals(low, lo, 0.0, "column " + c);
            assertEquals(high, hi, 0.0, "column " + c);
            assertTrue(e.x.contains(t.get(from)) && e.x.contains(t.get(to - 1)), "column " + c + "'s ends");
        }
    }

    @Test
    void aShortSeriesIsKeptWholeAndGapsStay() {
        List<Double> t = List.of(0.0, 1.0, 2.0), y = List.of(1.0, Double.NaN, 3.0);
        Envelope e = Envelope.of(t, y, 900);
        assertEquals(t, e.x);
        assertEquals(y, e.y);
        List<Double> lt = new ArrayList<>(), ly = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            lt.add((double) i);
            ly.add(Double.NaN);
        }
        Envelope nan = Envelope.of(lt, ly, 10);
        assertTrue(nan.y.stream().allMatch(v -> v.isNaN()) && nan.x.size() == 20, "a column without values keeps its ends: " + nan.x);
    }
}
