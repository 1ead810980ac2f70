package jacabot.sim.viewer;

import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.geom.Vec2;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.Locale;
import java.util.function.Supplier;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.Timer;

/**
 * The Swing viewer: the world top-down, repainted 25 times a second from snapshots, with pause,
 * single step, slower/faster (real time × factor) and "fast" (as fast as possible); boxes,
 * cylinders and robots can be dragged with the mouse, as in Webots. It drives nothing itself: pass
 * a {@link SimRunner} with the controller ({@code jacabot world view WORLD.json [--wander]} watches a
 * world with the demo pattern).
 */
public final class WorldViewer extends JPanel {
    private static final long serialVersionUID = 1L;

    private final transient SimRunner runner;
    private final transient Supplier<String> note;
    private transient WorldSnapshot snapshot;
    private String dragged;

    public WorldViewer(SimRunner runner) {
        this(runner, () -> "");
    }

    /** @param note more words for the status line, e.g. how far the run lags ("" for none) */
    public WorldViewer(SimRunner runner, Supplier<String> note) {
        this.runner = runner;
        this.note = note;
        this.snapshot = runner.world().snapshot();
        setPreferredSize(new Dimension(760, 820));
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                dragged = pick(worldPoint(e));
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                if (dragged != null) {
                    Vec2 p = worldPoint(e);
                    runner.world().supervisor().move(dragged, p.x(), p.z());
                    refresh();
                }
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                dragged = null;
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        new Timer(40, e -> refresh()).start();
    }

    private Vec2 worldPoint(MouseEvent e) {
        return WorldRenderer.view(snapshot, getWidth(), getHeight()).toWorld(e.getX(), e.getY());
    }

    /** The movable thing under a world point, or null. */
    private String pick(Vec2 p) {
        String best = null;
        double bestDistance = Double.POSITIVE_INFINITY;
        for (ObjectState o : snapshot.objects()) {
            if (o.kind() == ObjectKind.WALL) {
                continue;
            }
            double d = o.pose().position().distanceTo(p);
            if (d <= Math.max(o.sizeX(), o.sizeZ()) / 2 + 0.01 && d < bestDistance) {
                best = o.id();
                bestDistance = d;
            }
        }
        return best;
    }

    private void refresh() {
        snapshot = runner.world().snapshot();
        repaint();
    }

    @Override
    protected void paintComponent(Graphics g) {
        super.paintComponent(g);
        String status = String.format(Locale.ROOT, "%s%s ×%.2f, measured ×%.1f", runner.isPaused() ? "paused, " : "",
                runner.mode().name().toLowerCase(Locale.ROOT), runner.speedFactor(), runner.realTimeFactor());
        WorldRenderer.paint((Graphics2D) g, snapshot, getWidth(), getHeight(), status);
        String more = note.get();
        if (more != null && !more.isEmpty()) {
            // in red on the footer's first row, right of the camera strip: seen, and never cut off the status line
            Graphics2D g2 = (Graphics2D) g;
            g2.setColor(new Color(255, 90, 80));
            var font = new Font(Font.SANS_SERIF, Font.BOLD, 12);
            int room = getWidth() - 290;
            if (g2.getFontMetrics(font).stringWidth(more) > room) {
                font = font.deriveFont(10f);
            }
            g2.setFont(font);
            int w = g2.getFontMetrics().stringWidth(more);
            g2.drawString(more, Math.max(280, getWidth() - 10 - w), getHeight() - WorldRenderer.FOOTER + 18);
        }
    }

    /** Opens a window on the runner's world and starts the runner. */
    public static JFrame open(SimRunner runner) {
        return open(runner, () -> "");
    }

    /** Opens a window on the runner's world, {@code note} added to its status line, and starts the runner. */
    public static JFrame open(SimRunner runner, Supplier<String> note) {
        WorldViewer viewer = new WorldViewer(runner, note);
        JFrame frame = new JFrame("jacabot · " + runner.world().name());
        JPanel buttons = new JPanel();
        JButton pause = new JButton("pause");
        pause.addActionListener(e -> {
            runner.setPaused(!runner.isPaused());
            pause.setText(runner.isPaused() ? "run" : "pause");
        });
        JButton step = new JButton("step");
        step.addActionListener(e -> runner.singleStep());
        JButton slower = new JButton("slower");
        slower.addActionListener(e -> {
            runner.setMode(SimRunner.Mode.REAL_TIME);
            runner.setSpeedFactor(runner.speedFactor() / 2);
        });
        JButton faster = new JButton("faster");
        faster.addActionListener(e -> {
            runner.setMode(SimRunner.Mode.REAL_TIME);
            runner.setSpeedFactor(runner.speedFactor() * 2);
        });
        JButton fast = new JButton("fast");
        fast.addActionListener(e -> runner.setMode(SimRunner.Mode.FAST));
        for (JButton b : new JButton[] {pause, step, slower, faster, fast}) {
            buttons.add(b);
        }
        frame.setLayout(new BorderLayout());
        frame.add(viewer, BorderLayout.CENTER);
        frame.add(buttons, BorderLayout.SOUTH);
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.pack();
        frame.setVisible(true);
        runner.start();
        return frame;
    }
}
