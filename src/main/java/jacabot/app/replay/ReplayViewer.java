package jacabot.app.replay;

import jacabot.sim.viewer.WorldRenderer;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.function.IntConsumer;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.Timer;

/**
 * Plays a recorded run back: the world as the viewer draws it, with play/pause, step back and
 * forward, a speed factor and a time slider. Every position change is handed to a listener
 * (the inspector shows the agent's mind at the same instant).
 */
public final class ReplayViewer extends JPanel {
    private static final double[] SPEEDS = {0.25, 0.5, 1, 2, 5, 10, 50};

    private final Replay replay;
    private final IntConsumer onFrame;
    private final JSlider slider;
    private final JButton play = new JButton("play");
    private final JLabel time = new JLabel();
    private final JComboBox<String> speed = new JComboBox<>();
    private final Timer timer;
    private final Canvas canvas = new Canvas();
    private int index;
    private long playStartWall;
    private long playStartSim;

    public ReplayViewer(Replay replay, IntConsumer onFrame) {
        super(new BorderLayout());
        this.replay = replay;
        this.onFrame = onFrame;
        slider = new JSlider(0, Math.max(0, replay.frames().size() - 1), 0);
        for (double s : SPEEDS) {
            speed.addItem("x" + (s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s)));
        }
        speed.setSelectedItem("x1");
        JButton back = new JButton("<");
        JButton forward = new JButton(">");
        back.setToolTipText("one control step back");
        forward.setToolTipText("one control step forward");
        JPanel controls = new JPanel();
        controls.add(play);
        controls.add(back);
        controls.add(forward);
        controls.add(speed);
        controls.add(time);
        JPanel south = new JPanel(new BorderLayout());
        south.add(slider, BorderLayout.CENTER);
        south.add(controls, BorderLayout.SOUTH);
        add(canvas, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
        canvas.setPreferredSize(new Dimension(640, 640));
        timer = new Timer(33, e -> tick());
        play.addActionListener(e -> setPlaying(!timer.isRunning()));
        back.addActionListener(e -> {
            setPlaying(false);
            show(index - 1);
        });
        forward.addActionListener(e -> {
            setPlaying(false);
            show(index + 1);
        });
        speed.addActionListener(e -> restartClock());
        slider.addChangeListener(e -> {
            if (slider.getValue() != index) {
                show(slider.getValue());
                restartClock();
            }
        });
        show(0);
    }

    /** Opens the replay in a window. */
    public static JFrame open(Replay replay, IntConsumer onFrame) {
        JFrame f = new JFrame("jacabot replay: " + replay.dir());
        f.setContentPane(new ReplayViewer(replay, onFrame));
        f.pack();
        f.setLocationByPlatform(true);
        f.setVisible(true);
        return f;
    }

    private double speedFactor() {
        return SPEEDS[Math.max(0, speed.getSelectedIndex())];
    }

    private void setPlaying(boolean on) {
        if (on) {
            if (index >= replay.frames().size() - 1) {
                show(0);
            }
            restartClock();
            timer.start();
        } else {
            timer.stop();
        }
        play.setText(on ? "pause" : "play");
    }

    private void restartClock() {
        playStartWall = System.nanoTime();
        playStartSim = replay.frames().get(index).timeMs();
    }

    private void tick() {
        long sim = playStartSim + (long) ((System.nanoTime() - playStartWall) / 1e6 * speedFactor());
        int next = replay.indexAt(sim);
        if (next != index) {
            show(next);
        }
        if (index >= replay.frames().size() - 1) {
            setPlaying(false);
        }
    }

    /** Moves to frame {@code i} (clamped). */
    public void show(int i) {
        index = Math.max(0, Math.min(replay.frames().size() - 1, i));
        slider.setValue(index);
        var f = replay.frames().get(index);
        time.setText(String.format("t = %.2f s / %.1f s", f.timeMs() / 1000.0,
                replay.frames().get(replay.frames().size() - 1).timeMs() / 1000.0));
        canvas.repaint();
        onFrame.accept(index);
    }

    /** Paints frame {@code i} into an image (headless frames, screenshots). */
    public static BufferedImage render(Replay replay, int i, int width, int height) {
        var img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        WorldRenderer.paint(g, replay.world(i), width, height, status(replay, i));
        g.dispose();
        return img;
    }

    private static String status(Replay replay, int i) {
        var f = replay.frames().get(i);
        return "replay " + (i + 1) + "/" + replay.frames().size() + (f.commands().isEmpty() ? "" : "  " + String.join(" ", f.commands()));
    }

    private final class Canvas extends JPanel {
        @Override
        protected void paintComponent(Graphics g) {
            WorldRenderer.paint((Graphics2D) g, replay.world(index), getWidth(), getHeight(), status(replay, index));
        }
    }
}
