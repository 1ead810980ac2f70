package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
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

    @Test
    void redColumnsReadRowByRowAreTheColumnsHoldingARedPixel() {
        Random random = new Random(7);
        int[] palette = {GREY, RED, BEIGE, 0x2A1010, 0x291010, 0x501E28, 0x50282A, 0x502828};
        for (int n = 0; n < 2_000; n++) {
            int w = 1 + random.nextInt(70), h = 1 + random.nextInt(10);
            int[] framed = new int[2 + w * h];
            framed[0] = w;
            framed[1] = h;
            double redShare = random.nextInt(4) == 0 ? 0 : random.nextDouble() * 0.2;
            for (int i = 2; i < framed.length; i++) {
                framed[i] = random.nextDouble() < redShare ? palette[1 + random.nextInt(palette.length - 1)]
                        : random.nextBoolean() ? palette[random.nextInt(palette.length)] : random.nextInt(1 << 24);
            }
            boolean[] expected = new boolean[w];
            boolean any = false;
            for (int c = 0; c < w; c++) { // a column at a time, every pixel tested
                for (int y = 0; y < h; y++) {
                    int p = framed[2 + y * w + c];
                    expected[c] |= ObjectPickingMiddleware.isRed((p >> 16) & 0xFF, (p >> 8) & 0xFF, p & 0xFF);
                }
                any |= expected[c];
            }
            boolean[] got = CylinderSighting.redColumns(framed, w, h);
            if (any) {
                assertTrue(Arrays.equals(expected, got), "image " + n);
            } else {
                assertTrue(got == null, "image " + n + " has no red pixel");
            }
        }
    }

    @Test
    void theRedLevelsTableAgreesWithTheRedTestOnEveryColour() {
        int red = 0;
        for (int r = 0; r < 256; r++) {
            int below = CylinderSighting.GREEN_BLUE_BELOW[r];
            for (int g = 0; g < 256; g++) {
                for (int b = 0; b < 256; b++) {
                    boolean isRed = ObjectPickingMiddleware.isRed(r, g, b);
                    if ((g < below && b < below) != isRed) {
                        throw new AssertionError("colour " + r + ", " + g + ", " + b + ": the test says " + isRed);
                    }
                    red += isRed ? 1 : 0;
                }
            }
        }
        assertTrue(red > 0 && red < 256 * 256 * 256, "some colours are red, not all: " + red);
    }
}
