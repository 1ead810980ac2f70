package jacabot.sim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimRunner;
import jacabot.sim.TestWorlds;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** The viewer's note (e.g. a run's lag) is painted in red on the footer; no note, no red there. Off screen. */
class WorldViewerNoteTest {
    static {
        System.setProperty("java.awt.headless", "true");
    }

    private static int redPixels(String note) {
        var viewer = new WorldViewer(new SimRunner(TestWorlds.world(""), null), () -> note);
        viewer.setSize(760, 820);
        var img = new BufferedImage(760, 820, BufferedImage.TYPE_INT_RGB);
        var g = img.createGraphics();
        viewer.paint(g);
        g.dispose();
        int red = 0;
        for (int y = 820 - WorldRenderer.FOOTER; y < 820; y++) {
            for (int x = 280; x < 760; x++) {
                int c = img.getRGB(x, y);
                if (((c >> 16) & 0xFF) > 200 && ((c >> 8) & 0xFF) < 140 && (c & 0xFF) < 140) {
                    red++;
                }
            }
        }
        return red;
    }

    @Test
    void aNoteIsPaintedInRedOnTheFooter() {
        assertEquals(0, redPixels(""));
        assertTrue(redPixels("LAG: world 6.0 s behind real time (×16 requested, ×9.3 achieved)") > 100);
    }
}
