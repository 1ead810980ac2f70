package jacabot.sim.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.geom.Vec2;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Paints into images only: no display needed (java.awt.headless). */
class WorldRendererTest {
    static {
        System.setProperty("java.awt.headless", "true");
    }

    private static int[] rgb(BufferedImage img, double[] p) {
        int c = img.getRGB((int) Math.round(p[0]), (int) Math.round(p[1]));
        return new int[] {(c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF};
    }

    @Test
    void xIsRightZIsDownAndObjectsHaveTheirColours() {
        SimWorld w = TestWorlds.world("\"cylinders\": [{\"id\": \"red1\", \"x\": 0.3, \"z\": 0.0, \"radius\": 0.03}],"
                + "\"boxes\": [{\"id\": \"b\", \"x\": 0.0, \"z\": 0.3, \"size\": 0.1, \"color\": \"blue\"}],"
                + "\"storage\": {\"x\": 0.41, \"z\": -0.41, \"radius\": 0.06}");
        WorldSnapshot s = w.snapshot();
        BufferedImage img = PngRenderer.render(s, 600, 660);
        WorldRenderer.View v = WorldRenderer.view(s, 600, 660);
        double[] cyl = v.toScreen(0.3, 0.0), box = v.toScreen(0.0, 0.3), floor = v.toScreen(-0.2, -0.2);
        assertTrue(cyl[0] > v.toScreen(0, 0)[0], "+x is right");
        assertTrue(box[1] > v.toScreen(0, 0)[1], "+z is down");
        assertEquals(255, rgb(img, cyl)[0]);
        assertEquals(32, rgb(img, cyl)[1]);
        assertEquals(230, rgb(img, box)[2]);
        int[] f = rgb(img, floor);
        assertEquals(140, f[0]);
        assertEquals(f[0], f[1]);
        int[] storage = rgb(img, v.toScreen(0.41, -0.41));
        assertTrue(storage[1] > storage[0], "the storage area is tinted green");
    }

    @Test
    void screenAndWorldPointsRoundTrip() {
        WorldSnapshot s = TestWorlds.world("").snapshot();
        WorldRenderer.View v = WorldRenderer.view(s, 500, 500);
        double[] p = v.toScreen(0.12, -0.34);
        Vec2 back = v.toWorld(p[0], p[1]);
        assertEquals(0.12, back.x(), 1e-12);
        assertEquals(-0.34, back.z(), 1e-12);
    }

    @Test
    void aHeadlessPngShowsTheTrajectory(@TempDir Path dir) throws Exception {
        SimWorld w = TestWorlds.khepera(-0.2, 0, 0, "");
        w.robot("k").setSpeeds(100, 100);
        w.step(4000);
        Path png = dir.resolve("world.png");
        PngRenderer.write(w, png, 400, 460);
        assertTrue(Files.size(png) > 1000);
        BufferedImage img = ImageIO.read(png.toFile());
        WorldRenderer.View v = WorldRenderer.view(w.snapshot(), 400, 460);
        int[] trail = rgb(img, v.toScreen(-0.19, 0)); // behind the robot, on its way
        assertEquals(255, trail[0]);
        assertEquals(140, trail[1]);
    }
}
