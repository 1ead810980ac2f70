package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PinnedWatchTest {
    private static PinnedWatch watch() {
        return new PinnedWatch(250, 40, 15, 1500);
    }

    @Test
    void bothSensorsHoldingTheSameHighReadingWhileDrivingIsPinnedOnlyAfterTheHold() {
        PinnedWatch w = watch();
        long t = 0;
        // wide held-out world 297 seed 1: a thin wall's end between the rays, both about 370
        for (; t < 1500; t += 40) {
            assertFalse(w.read(370 + (t / 40) % 3, 368, true, t), "at " + t + " ms");
        }
        assertTrue(w.read(371, 369, true, t));
    }

    @Test
    void climbingReadingsLowOnesADifferenceOrAStopAreNotPinned() {
        PinnedWatch climbing = watch(), low = watch(), apart = watch(), still = watch(), broken = watch();
        boolean any = false;
        for (long t = 0; t <= 3000; t += 40) {
            any |= climbing.read(250 + t / 10.0, 250 + t / 10.0, true, t); // a wall met head-on
            any |= low.read(200, 200, true, t);
            any |= apart.read(400, 330, true, t);
            any |= still.read(370, 370, false, t); // not driving
            any |= broken.read(t % 800 < 40 ? 100 : 370, 370, true, t); // the hold begins again
        }
        assertFalse(any);
    }
}
