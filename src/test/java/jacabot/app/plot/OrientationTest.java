package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.app.replay.Replay;
import jacabot.app.replay.ReplayViewer;
import jacabot.app.replay.SyntheticRun;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.viewer.PngRenderer;
import jacabot.sim.viewer.WorldRenderer;
import java.awt.image.BufferedImage;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * One orientation for every picture: in the navigation world the storage area (x 0.41, z -0.41)
 * is in the top-right quadrant and the cylinder red2 (x -0.3, z 0.15) in the bottom-left one, in
 * {@code world render}'s PNG, in a replay frame and in {@code events.png} alike (x to the right,
 * z down).
 */
class OrientationTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void theSameQuadrantsInWorldRenderReplayFramesAndPlots(@TempDir Path dir) throws Exception {
        SimWorld world = SimWorld.load(ROOT.resolve("worlds/navigation.json"));
        WorldSnapshot start = world.snapshot();
        check("world render", PngRenderer.render(start, 600, 660), start);

        SyntheticRun.write(dir, 8);
        Replay replay = Replay.open(dir);
        check("replay frame", ReplayViewer.render(replay, 10, 640, 640), replay.world(10));

        RunPlots.writeAll(dir, new PrintStream(OutputStream.nullOutputStream()));
        check("events.png", ImageIO.read(dir.resolve("events.png").toFile()), MapPlot.background(start));
    }

    /** Asserts the storage's green tint is mostly top-right and red2's red mostly bottom-left of the arena's centre. */
    private static void check(String what, BufferedImage img, WorldSnapshot s) {
        double[] c = WorldRenderer.view(s, img.getWidth(), img.getHeight()).toScreen(0, 0);
        int[] green = new int[4], red = new int[4];
        for (int y = 0; y < img.getHeight() - 60; y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if (Math.abs(y - c[1]) < 20 || Math.abs(x - c[0]) < 20) {
                    continue; // red1 sits on the x axis
                }
                int p = img.getRGB(x, y), r = (p >> 16) & 255, g = (p >> 8) & 255, b = p & 255;
                int q = (x > c[0] ? 1 : 0) + (y > c[1] ? 2 : 0); // 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right
                if (g > r + 25 && g > b + 25) {
                    green[q]++;
                }
                if (r > 200 && g < 80 && b < 80) {
                    red[q]++;
                }
            }
        }
        assertEquals(1, argmax(green), what + ": the storage area top-right, green pixels per quadrant "
                + Arrays.toString(green));
        assertEquals(2, argmax(red), what + ": red2 bottom-left, red pixels per quadrant " + Arrays.toString(red));
    }

    private static int argmax(int[] v) {
        int best = 0;
        for (int i = 1; i < v.length; i++) {
            best = v[i] > v[best] ? i : best;
        }
        return best;
    }
}
