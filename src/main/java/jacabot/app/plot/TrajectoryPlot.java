package jacabot.app.plot;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.geom.Rgb;
import jacabot.sim.viewer.PngRenderer;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * {@code trajectory.png}: the world at the run's end as the viewer paints it (x right, z down,
 * metre ticks), the robots' paths, and under it a legend of what the colours are.
 */
public final class TrajectoryPlot {
    /** Pixels under the picture for the legend. */
    static final int LEGEND = 40;

    private TrajectoryPlot() {
    }

    /** Writes the world now, with its legend, into {@code png} ({@code size} pixels wide, the arena square). */
    public static void write(SimWorld world, Path png, int size) throws IOException {
        ImageIO.write(draw(world.snapshot(), size), "png", png.toFile());
    }

    /** {@return the picture with its legend} */
    static BufferedImage draw(WorldSnapshot s, int size) {
        BufferedImage world = PngRenderer.render(s, size, size);
        BufferedImage img = new BufferedImage(size, size + LEGEND, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.drawImage(world, 0, 0, null);
            g.setColor(new Color(30, 30, 36));
            g.fillRect(0, size, size, LEGEND);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            MapPlot.legend(g, entries(s), size, 10, size + 16);
        } finally {
            g.dispose();
        }
        return img;
    }

    /** The legend's entries: only what this world has (the viewer's colours). */
    static Map<String, Color> entries(WorldSnapshot s) {
        var out = new LinkedHashMap<String, Color>();
        s.robots().forEach(r -> out.put("robot " + r.name() + " (white: heading)", color(r.color())));
        out.put("path", new Color(255, 140, 0));
        if (s.robots().stream().anyMatch(r -> !r.rays().isEmpty())) {
            out.put("distance sensor rays (green: free, red: near)", new Color(60, 220, 60));
        }
        if (s.storage() != null) {
            out.put("storage area", new Color(60, 200, 90));
        }
        if (s.charger() != null) {
            out.put("charger", new Color(240, 210, 40));
        }
        for (ObjectState o : s.objects()) {
            if (o.kind() == ObjectKind.CYLINDER) {
                out.putIfAbsent("cylinder (yellow ring: carried)", color(o.color()));
            } else if (o.kind() == ObjectKind.BOX) {
                out.putIfAbsent(o.movable() ? "movable box" : "box", color(o.color()));
            }
        }
        out.put("walls", new Color(200, 200, 200));
        return out;
    }

    private static Color color(Rgb c) {
        return new Color(c.red(), c.green(), c.blue());
    }
}
