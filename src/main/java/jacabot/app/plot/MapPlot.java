package jacabot.app.plot;

import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.viewer.WorldRenderer;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A run's trajectory and its events drawn over the world's geometry at the start, in the
 * renderer's one orientation (+x right, +z down, metre ticks on the edges), with a legend:
 * {@code events.png}, and several runs overlaid for {@code jacabot plot RUN_A RUN_B}.
 */
public final class MapPlot {
    /** Colours of the tracks, one per run overlaid. */
    private static final Color[] TRACKS = {new Color(255, 140, 0), new Color(60, 160, 255), new Color(230, 60, 200),
            new Color(120, 220, 120)};
    /** Colours of the events, by kind; kinds not listed take grey. */
    private static final Map<String, Color> KINDS = Map.of("pick", new Color(230, 30, 30), "delivery",
            new Color(40, 200, 80), "obstacle", new Color(250, 250, 250), "recharge", new Color(250, 220, 40), "charged",
            new Color(200, 160, 0), "low battery", new Color(255, 90, 90), "resume", new Color(90, 200, 255), "mark",
            new Color(200, 90, 255), "world", new Color(170, 170, 170), "failure", new Color(255, 0, 0));

    private MapPlot() {
    }

    /** One run's path: its name for the legend, and its points {x, z}. */
    public record Track(String name, List<double[]> points) {
    }

    /** An event at a place: its kind (legend) and where the robot was. */
    public record Spot(String kind, double x, double z) {
    }

    /** {@return the world without its robots, as a background} */
    static WorldSnapshot background(WorldSnapshot start) {
        var objects = new ArrayList<ObjectState>();
        for (ObjectState o : start.objects()) {
            if (o.kind() != ObjectKind.ROBOT) {
                objects.add(o);
            }
        }
        return new WorldSnapshot(start.name(), 0, start.arena(), start.storage(), start.charger(), objects, List.of());
    }

    /** Draws the tracks and spots over {@code start}'s geometry. */
    public static BufferedImage draw(WorldSnapshot start, List<Track> tracks, List<Spot> spots, String title, int size) {
        BufferedImage img = new BufferedImage(size, size + 80, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            WorldSnapshot world = background(start);
            WorldRenderer.paint(g, world, img.getWidth(), img.getHeight(), title);
            WorldRenderer.View v = WorldRenderer.view(world, img.getWidth(), img.getHeight());
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            var legend = new LinkedHashMap<String, Color>();
            for (int k = 0; k < tracks.size(); k++) {
                Track t = tracks.get(k);
                Color c = TRACKS[k % TRACKS.length];
                Path2D path = new Path2D.Double();
                for (int i = 0; i < t.points().size(); i++) {
                    double[] p = v.toScreen(t.points().get(i)[0], t.points().get(i)[1]);
                    if (i == 0) {
                        path.moveTo(p[0], p[1]);
                    } else {
                        path.lineTo(p[0], p[1]);
                    }
                }
                g.setColor(c);
                g.setStroke(new BasicStroke(1.5f));
                g.draw(path);
                legend.put(t.name(), c);
            }
            for (Spot s : spots) {
                Color c = KINDS.getOrDefault(s.kind(), Color.LIGHT_GRAY);
                double[] p = v.toScreen(s.x(), s.z());
                g.setColor(c);
                g.fill(new Ellipse2D.Double(p[0] - 5, p[1] - 5, 10, 10));
                g.setColor(Color.BLACK);
                g.draw(new Ellipse2D.Double(p[0] - 5, p[1] - 5, 10, 10));
                legend.putIfAbsent("\u25cf " + s.kind(), c);
            }
            legend(g, legend, img.getWidth(), 26, img.getHeight() - 40);
        } finally {
            g.dispose();
        }
        return img;
    }

    /**
     * A legend in rows from ({@code x0}, {@code y0}) (the first row's baseline), under the arena:
     * it never hides a corner of the world.
     */
    static void legend(Graphics2D g, Map<String, Color> entries, int width, int x0, int y0) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        int x = x0, y = y0;
        for (var e : entries.entrySet()) {
            int w = g.getFontMetrics().stringWidth(e.getKey());
            if (x + w + 24 > width) {
                x = x0;
                y += 14;
            }
            g.setColor(e.getValue());
            g.fillRect(x, y - 8, 14, 8);
            g.setColor(Color.WHITE);
            g.drawString(e.getKey(), x + 18, y);
            x += w + 32;
        }
    }
}
