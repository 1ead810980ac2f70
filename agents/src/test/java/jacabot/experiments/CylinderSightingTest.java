package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class CylinderSightingTest {
    private static final int GREY = 0x8C8C8C, RED = 0xC81E1E, BEIGE = 0xFFF0C8;

    /** A 64x8 image framed as the link sends it, grey, with {@code colour} in columns from..to-1 of rows 3-4. */
    static int[] image(int colour, int from, int to) {
        int w = 64, h = 8;
        int[] framed = new int[2 + w * h];
        framed[0] = w;
        framed[1] = h;
        Arrays.fill(framed, 2, framed.length, GREY);
        for (int y = 3; y <= 4; y++) {
            for (int x = from; x < to; x++) {
                framed[2 + y * w + x] = colour;
            }
        }
        return framed;
    }

    @Test
    void theWidestRedRunGivesTheOffsetAndARoughDistance() {
        int[] img = image(RED, 40, 43);
        // a narrower run further left must not win
        img[2 + 3 * 64 + 5] = RED;
        var s = CylinderSighting.find(img, 60).orElseThrow();
        assertEquals((41.5 - 32) * 60 / 64.0, s.offset(), 1e-9, "right of centre");
        assertEquals(3, s.columns());
        assertEquals(0.0125 / Math.tan(Math.toRadians(3 * 60 / 64.0 / 2)), s.distance(), 1e-9);
        assertTrue(s.distance() > 0.4 && s.distance() < 0.6, "three columns: about half a metre");
    }

    @Test
    void everyRedRunComesWidestFirst() {
        int[] img = image(RED, 40, 43);
        img[2 + 3 * 64 + 5] = RED;
        img[2 + 3 * 64 + 20] = RED;
        var all = CylinderSighting.all(img, 60);
        assertEquals(3, all.size());
        assertEquals(CylinderSighting.find(img, 60).orElseThrow(), all.get(0), "the widest, as find gives it");
        assertEquals(3, all.get(0).columns());
        assertTrue(all.get(1).offset() < all.get(2).offset(), "of runs as wide, the leftmost first");
        assertTrue(CylinderSighting.all(image(BEIGE, 10, 30), 60).isEmpty());
    }

    @Test
    void aRedRunLeftOfCentreHasANegativeOffset() {
        assertTrue(CylinderSighting.find(image(RED, 0, 2), 60).orElseThrow().offset() < -25);
    }

    @Test
    void noRedOrABadFrameIsNoSighting() {
        assertTrue(CylinderSighting.find(image(BEIGE, 10, 30), 60).isEmpty(), "a beige box is not red");
        assertTrue(CylinderSighting.find(new int[] {64, 8, RED}, 60).isEmpty(), "pixels missing");
        assertTrue(CylinderSighting.find(new int[] {-1, 8}, 60).isEmpty());
        assertTrue(CylinderSighting.find(new int[0], 60).isEmpty());
    }
}
