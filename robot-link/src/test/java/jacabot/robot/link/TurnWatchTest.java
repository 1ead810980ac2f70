package jacabot.robot.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** When the simulation thread stops taking the middleware's turns: its share of a core, window by window. */
class TurnWatchTest {
    /** A thread that works {@code share} of each microsecond of wall time, 1 µs per turn. */
    private static final class Clocks {
        long wall, cpu;
        double share;

        void turn() {
            wall += 1_000;
            cpu += Math.round(1_000 * share);
        }
    }

    /** {@return the turn (1-based) after which turns stop, or -1 within {@code max} turns} */
    private static long stopsAfter(TurnWatch watch, Clocks clocks, double[] sharePerWindow, long max) {
        for (long t = 1; t <= max; t++) {
            clocks.share = sharePerWindow[(int) Math.min(sharePerWindow.length - 1, (t - 1) / TurnWatch.WINDOW)];
            clocks.turn();
            assertTrue(watch.takes());
            if (watch.taken()) {
                assertFalse(watch.takes(), "no turn after the watch said stop");
                return t;
            }
        }
        return -1;
    }

    @Test
    void aThreadWithItsCoreGoesOnTakingTurns() {
        var c = new Clocks();
        assertEquals(-1, stopsAfter(new TurnWatch(() -> c.cpu, () -> c.wall), c, new double[] {0.95}, 10 * TurnWatch.WINDOW));
    }

    @Test
    void twoWindowsInARowBelowHalfACoreStopTheTurns() {
        var c = new Clocks();
        // windows: full, low, low: the check after the third window's turns ends them
        long stop = stopsAfter(new TurnWatch(() -> c.cpu, () -> c.wall), c, new double[] {1.0, 0.3, 0.3}, 10 * TurnWatch.WINDOW);
        assertEquals(3 * TurnWatch.WINDOW + 1, stop);
    }

    @Test
    void oneLowWindowAloneDoesNot() {
        var c = new Clocks();
        assertEquals(-1, stopsAfter(new TurnWatch(() -> c.cpu, () -> c.wall), c,
                new double[] {1.0, 0.3, 0.9, 0.2, 0.8, 0.9}, 10 * TurnWatch.WINDOW));
    }

    @Test
    void whereTheThreadsCpuTimeCannotBeMeasuredTurnsNeverStop() {
        var c = new Clocks();
        assertEquals(-1, stopsAfter(new TurnWatch(() -> -1, () -> c.wall), c, new double[] {0.1}, 10 * TurnWatch.WINDOW));
    }

    @Test
    void aMeasurersThresholdIsAShareAndAnythingElseLeavesTheDefault() {
        assertEquals(0.7, TurnWatch.minShare(null));
        assertEquals(0.0, TurnWatch.minShare("0"));
        assertEquals(0.5, TurnWatch.minShare(" 0.5 "));
        assertEquals(0.7, TurnWatch.minShare("half"));
        assertEquals(0.7, TurnWatch.minShare("1.5"));
        assertEquals(0.7, TurnWatch.minShare("NaN"));
    }
}
