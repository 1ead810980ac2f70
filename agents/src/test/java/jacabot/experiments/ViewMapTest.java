package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ViewMapTest {
    /** A 2 m square arena, the storage point in its (+, +) corner. */
    private final ViewMap map = new ViewMap(2.0, 2.0);

    @Test
    void aLookMarksTheFloorAheadWithinRangeAndNothingBehind() {
        map.looked(0, 0, 0); // facing +x
        assertTrue(map.seen(0.625, 0.125, 0.9), "0.64 m ahead, 11 degrees off");
        assertFalse(map.seen(0.875, 0.625, 0.9), "40 degrees off: out of the camera's field");
        assertFalse(map.seen(-0.625, 0.125, 0.9), "behind the robot");
        assertTrue(map.seen(-0.125, -0.125, 0.9), "round the robot");
        assertFalse(map.seen(0.625, 0.125, 0.5), "looked at from farther than 0.5 m");
    }

    @Test
    void theNearestUnseenCellOffTheStorageAreaIsTheNextAndAllSeenBeginsAgain() {
        assertArrayEquals(new double[] {0.125, 0.125}, map.nearestUnseen(0.1, 0.1, 0.9, 0.75, 0.75, 0.3), 1e-9);
        map.looked(0, 0, 0);
        map.looked(0, 0, 180);
        double[] next = map.nearestUnseen(0, 0, 0.9, 0.75, 0.75, 0.3);
        assertFalse(map.seen(next[0], next[1], 0.9), "the point is unseen");
        assertTrue(Math.hypot(next[0] - 0.75, next[1] - 0.75) >= 0.3, "off the storage area");
        for (int k = 0; k < 64; k++) {
            map.giveUp(-1 + (k / 8 + 0.5) * 0.25, -1 + (k % 8 + 0.5) * 0.25);
        }
        assertArrayEquals(new double[] {-0.125, -0.125}, map.nearestUnseen(-0.1, -0.1, 0.9, 0.75, 0.75, 0.3), 1e-9,
                "every cell given up: the map began again");
    }
}
