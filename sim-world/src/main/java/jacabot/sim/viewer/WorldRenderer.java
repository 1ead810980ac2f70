package jacabot.sim.viewer;

import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.world.AreaSpec;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.Locale;

/**
 * Paints a {@link WorldSnapshot} top-down with Java2D in the project's one orientation: +x to the
 * right and +z down, as seen from above (a heading, clockwise from +x, turns clockwise on the
 * screen too); the inspector's canvas and every plot use the same. It draws the floor,
 * storage (green) and charger (yellow) areas, walls, boxes, cylinders, robots with their
 * trajectory and sensor rays (grey when disabled, green → red as the value rises), a camera strip
 * and a status line. Used by the Swing viewer and for headless PNGs; needs no display.
 */
public final class WorldRenderer {
    /** Pixels kept under the arena for the camera strip and the status line. */
    static final int FOOTER = 56;
    /** Room around the arena for the axes' labels. */
    private static final int MARGIN = 26;

    /** World ↔ screen mapping for one image size. */
    public record View(double scale, double originX, double originY) {
        /** {@return the screen point of a world point} */
        public double[] toScreen(double x, double z) {
            return new double[] {originX + x * scale, originY + z * scale};
        }

        /** {@return the world point under a screen point} */
        public Vec2 toWorld(double sx, double sy) {
            return new Vec2((sx - originX) / scale, (sy - originY) / scale);
        }
    }

    private WorldRenderer() {
    }

    /** {@return the mapping that fits the arena (walls included) into width × height pixels, above the footer} */
    public static View view(WorldSnapshot s, int width, int height) {
        double t = s.arena().wallThickness();
        double worldW = s.arena().width() + 2 * t, worldH = s.arena().depth() + 2 * t;
        double scale = Math.min((width - 2.0 * MARGIN) / worldW, (height - 2.0 * MARGIN - FOOTER) / worldH);
        return new View(scale, width / 2.0, MARGIN + (height - FOOTER - 2.0 * MARGIN) / 2.0);
    }

    /** Paints the snapshot; {@code status} is appended to the status line (e.g. the real-time factor), may be null. */
    public static void paint(Graphics2D g, WorldSnapshot s, int width, int height, String status) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(30, 30, 36));
        g.fillRect(0, 0, width, height);
        View v = view(s, width, height);
        AffineTransform saved = g.getTransform();
        // world (x, z) → screen: screenX = ox + x·k, screenY = oy + z·k
        g.transform(new AffineTransform(v.scale(), 0, 0, v.scale(), v.originX(), v.originY()));
        g.setStroke(new BasicStroke((float) (1.0 / v.scale())));
        g.setColor(color(s.arena().floorColor()));
        g.fill(new Rectangle2D.Double(-s.arena().halfWidth(), -s.arena().halfDepth(), s.arena().width(), s.arena().depth()));
        area(g, s.storage(), new Color(60, 200, 90, 120));
        area(g, s.charger(), new Color(240, 210, 40, 140));
        for (ObjectState o : s.objects()) {
            if (o.kind() != ObjectKind.ROBOT) {
                object(g, o);
            }
        }
        for (WorldSnapshot.RobotState r : s.robots()) {
            robot(g, r, v.scale());
        }
        g.setTransform(saved);
        axes(g, s, v);
        footer(g, s, width, height, status);
    }

    /** Ticks and labels in metres along the arena's top (x) and left (z) edges, and which way each axis runs. */
    private static void axes(Graphics2D g, WorldSnapshot s, View v) {
        double hw = s.arena().halfWidth(), hd = s.arena().halfDepth();
        double step = tickStep(Math.max(s.arena().width(), s.arena().depth()));
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        g.setColor(new Color(200, 200, 200));
        double[] corner = v.toScreen(-hw, -hd);
        for (double x = Math.ceil(-hw / step) * step; x <= hw + 1e-9; x += step) {
            double[] p = v.toScreen(x, -hd);
            g.draw(new Line2D.Double(p[0], corner[1] - 3, p[0], corner[1] - 8));
            String label = String.format(Locale.ROOT, "%.2f", x + 0.0);
            g.drawString(label, (float) (p[0] - g.getFontMetrics().stringWidth(label) / 2.0), (float) corner[1] - 10);
        }
        for (double z = Math.ceil(-hd / step) * step; z <= hd + 1e-9; z += step) {
            double[] p = v.toScreen(-hw, z);
            g.draw(new Line2D.Double(corner[0] - 3, p[1], corner[0] - 8, p[1]));
            AffineTransform saved = g.getTransform();
            g.translate(corner[0] - 10, p[1]);
            g.rotate(-Math.PI / 2);
            String label = String.format(Locale.ROOT, "%.2f", z + 0.0);
            g.drawString(label, -g.getFontMetrics().stringWidth(label) / 2f, 0);
            g.setTransform(saved);
        }
        double[] bottom = v.toScreen(-hw, hd);
        g.drawString("x (m) \u2192 right,  z (m) \u2193 down", (float) bottom[0], (float) bottom[1] + 18);
    }

    private static double tickStep(double side) {
        for (double step : new double[] {0.1, 0.25, 0.5, 1, 2, 5, 10}) {
            if (side / step <= 8) {
                return step;
            }
        }
        return 20;
    }

    private static Color color(Rgb c) {
        return new Color(c.red(), c.green(), c.blue());
    }

    private static void area(Graphics2D g, AreaSpec a, Color c) {
        if (a == null) {
            return;
        }
        g.setColor(c);
        g.fill(new Ellipse2D.Double(a.x() - a.radius(), a.z() - a.radius(), 2 * a.radius(), 2 * a.radius()));
    }

    private static void object(Graphics2D g, ObjectState o) {
        Pose p = o.pose();
        if (o.kind() == ObjectKind.CYLINDER) {
            double r = o.sizeX() / 2;
            Ellipse2D e = new Ellipse2D.Double(p.x() - r, p.z() - r, 2 * r, 2 * r);
            g.setColor(color(o.color()));
            g.fill(e);
            g.setColor(o.carriedBy() != null ? Color.YELLOW : Color.BLACK);
            g.draw(e);
            return;
        }
        AffineTransform saved = g.getTransform();
        g.translate(p.x(), p.z());
        g.rotate(Math.toRadians(p.heading()));
        Rectangle2D rect = new Rectangle2D.Double(-o.sizeX() / 2, -o.sizeZ() / 2, o.sizeX(), o.sizeZ());
        g.setColor(color(o.color()));
        g.fill(rect);
        g.setColor(o.movable() ? new Color(90, 90, 200) : Color.DARK_GRAY);
        g.draw(rect);
        g.setTransform(saved);
    }

    private static void robot(Graphics2D g, WorldSnapshot.RobotState r, double scale) {
        List<Pose> t = r.trajectory();
        if (t.size() > 1) {
            Path2D path = new Path2D.Double();
            path.moveTo(t.get(0).x(), t.get(0).z());
            for (int i = 1; i < t.size(); i++) {
                path.lineTo(t.get(i).x(), t.get(i).z());
            }
            g.setColor(new Color(255, 140, 0));
            g.draw(path);
        }
        for (WorldSnapshot.SensorRay ray : r.rays()) {
            double frac = Double.isNaN(ray.value()) ? -1 : Math.max(0, Math.min(1, ray.value() / ray.maxValue()));
            g.setColor(frac < 0 ? new Color(160, 160, 160, 120)
                    : new Color((int) (60 + 195 * frac), (int) (220 - 190 * frac), 60, 200));
            Vec2 a = ray.origin().position(), b = a.plus(ray.origin().forward().times(ray.range()));
            g.draw(new Line2D.Double(a.x(), a.z(), b.x(), b.z()));
        }
        Pose p = r.pose();
        double rad = r.radius();
        g.setColor(color(r.color()));
        g.fill(new Ellipse2D.Double(p.x() - rad, p.z() - rad, 2 * rad, 2 * rad));
        g.setColor(Color.WHITE);
        Vec2 nose = p.position().plus(p.forward().times(rad));
        g.setStroke(new BasicStroke((float) (2.0 / scale)));
        g.draw(new Line2D.Double(p.x(), p.z(), nose.x(), nose.z()));
        if (!Double.isNaN(r.armPosition())) {
            // the gripper: two fingers ahead of the body, apart when open, lighter when the arm is up
            double open = 1 - r.gripPosition();
            Vec2 f = p.forward(), side = Vec2.ofBearing(p.heading() + 90);
            g.setColor(new Color(220, 220, 220, (int) (90 + 160 * r.armPosition())));
            for (int s = -1; s <= 1; s += 2) {
                Vec2 base = p.position().plus(f.times(rad)).plus(side.times(s * (0.006 + 0.012 * open)));
                Vec2 tip = base.plus(f.times(0.03));
                g.draw(new Line2D.Double(base.x(), base.z(), tip.x(), tip.z()));
            }
        }
        g.setStroke(new BasicStroke((float) (1.0 / scale)));
    }

    private static void footer(Graphics2D g, WorldSnapshot s, int width, int height, String status) {
        int y0 = height - FOOTER + 4;
        int x = MARGIN;
        for (WorldSnapshot.RobotState r : s.robots()) {
            if (r.cameraImage() != null) {
                int px = Math.max(1, Math.min(4, 256 / r.cameraWidth()));
                int ph = Math.max(1, 24 / r.cameraHeight());
                for (int row = 0; row < r.cameraHeight(); row++) {
                    for (int col = 0; col < r.cameraWidth(); col++) {
                        g.setColor(new Color(r.cameraImage()[row * r.cameraWidth() + col]));
                        g.fillRect(x + col * px, y0 + row * ph, px, ph);
                    }
                }
                x += r.cameraWidth() * px + 10;
            }
        }
        StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%s  t = %.2f s", s.name(), s.timeMs() / 1000.0));
        for (WorldSnapshot.RobotState r : s.robots()) {
            line.append(String.format(Locale.ROOT, "  %s: contact %.1f s", r.name(), r.contactTime()));
            if (!Double.isNaN(r.battery())) {
                line.append(String.format(Locale.ROOT, ", battery %.0f/%.0f J", r.battery(), r.batteryMax()));
            }
            if (!Double.isNaN(r.armPosition())) {
                line.append(String.format(Locale.ROOT, ", arm %s, grip %s%s", r.armPosition() == 0 ? "up" : r.armPosition() == 1 ? "down" : "moving",
                        r.gripPosition() == 0 ? "open" : r.gripPosition() == 1 ? "closed" : "moving",
                        r.held() == null ? "" : ", holding " + r.held()));
            }
        }
        if (status != null) {
            line.append("  ").append(status);
        }
        g.setColor(Color.WHITE);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString(line.toString(), MARGIN, height - 8);
    }
}
