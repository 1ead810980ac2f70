package jacabot.sim.viewer;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.demo.Wander;
import jacabot.sim.io.WorldFileException;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Headless rendering: a world with the robots' trajectories into a PNG (Java2D, no display).
 * As a program: {@code PngRenderer WORLD.json OUT.png [SECONDS]} runs the {@link Wander} pattern for
 * SECONDS (default 60) of simulated time, then writes the picture.
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

    public static void main(String[] args) {
        System.setProperty("java.awt.headless", "true");
        if (args.length < 2) {
            System.err.println("usage: PngRenderer WORLD.json OUT.png [SECONDS]");
            System.exit(2);
        }
        try {
            SimWorld world = SimWorld.load(Path.of(args[0]));
            double seconds = args.length > 2 ? Double.parseDouble(args[2]) : 60;
            Wander wander = new Wander();
            while (world.time() < seconds) {
                wander.accept(world);
                world.step();
            }
            write(world, Path.of(args[1]), 800, 860);
            System.out.println("wrote " + args[1] + " after " + world.time() + " s of simulated time");
        } catch (WorldFileException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(2);
        } catch (IOException | NumberFormatException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(1);
        }
    }
}
