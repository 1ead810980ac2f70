package jacabot.sim.viewer;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Headless rendering: a world with the robots' trajectories into a PNG (Java2D, no display).
 * {@code jacabot world render WORLD.json --out OUT.png} uses it.
 */
public final class PngRenderer {
    private PngRenderer() {
    }

    /** {@return the snapshot painted into a new image} */
    public static BufferedImage render(WorldSnapshot s, int width, int height) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            WorldRenderer.paint(g, s, width, height, null);
        } finally {
            g.dispose();
        }
        return img;
    }

    /** Writes the world as it is now to a PNG file. */
    public static void write(SimWorld world, Path png, int width, int height) throws IOException {
        ImageIO.write(render(world.snapshot(), width, height), "png", png.toFile());
    }
}
