package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.demo.Wander;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.viewer.PngRenderer;
import jacabot.sim.viewer.WorldViewer;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine;

/** {@code jacabot world view} and {@code jacabot world render}: sim-world's viewer and renderer on a world file. */
final class WorldViewCommands {
    private WorldViewCommands() {
    }

    /** Loads a world (the current folder's file, else the installation's) or says why not. */
    private static SimWorld load(Path file) {
        try {
            return SimWorld.load(Installation.locate(file));
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
    }

    /** {@code jacabot world view FILE [--wander]}: the Swing viewer (needs a display). */
    @Command(name = "view", mixinStandardHelpOptions = true,
            description = "Opens the Swing viewer on a world file (pause, step, speed; drag objects). Needs a display.")
    static final class View implements Callable<Integer> {
        @CommandLine.Spec
        private CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", paramLabel = "FILE", description = "a world file")
        private Path file;

        @Option(names = "--wander", description = "drive the robots with the demo pattern (every device on, weave, turn away)")
        private boolean wander;

        @Override
        public Integer call() throws InterruptedException {
            SimWorld world = load(file);
            if (GraphicsEnvironment.isHeadless()) {
                throw new UserError("no display; `jacabot world render " + file + " --out world.png` draws the world headless");
            }
            SimRunner runner = new SimRunner(world, wander ? new Wander() : null);
            var closed = new CountDownLatch(1);
            SwingUtilities.invokeLater(() -> {
                JFrame frame = WorldViewer.open(runner);
                frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
                frame.addWindowListener(new WindowAdapter() {
                    @Override
                    public void windowClosed(WindowEvent e) {
                        closed.countDown();
                    }
                });
            });
            while (!closed.await(200, TimeUnit.MILLISECONDS)) {
                // the window's owner: returns when it is closed
            }
            runner.stop();
            return 0;
        }
    }

    /** {@code jacabot world render FILE --out PNG [--seconds S]}: a picture, headless. */
    @Command(name = "render", mixinStandardHelpOptions = true,
            description = "Draws a world file into a PNG, headless; with --seconds > 0 after the demo pattern drove that "
                    + "long (trajectories shown).")
    static final class Render implements Callable<Integer> {
        @CommandLine.Spec
        private CommandLine.Model.CommandSpec spec;

        @Parameters(index = "0", paramLabel = "FILE", description = "a world file")
        private Path file;

        @Option(names = "--out", paramLabel = "PNG", required = true, description = "the picture to write")
        private Path out;

        @Option(names = "--seconds", paramLabel = "S", description = "simulated seconds of the demo pattern first (default ${DEFAULT-VALUE})")
        private double seconds = 0;

        @Option(names = "--size", paramLabel = "W", description = "width in pixels; the height adds the status line (default ${DEFAULT-VALUE})")
        private int size = 800;

        @Override
        public Integer call() {
            if (!(seconds >= 0) || size < 50 || size > 10_000) {
                throw new UserError("--seconds must be >= 0 and --size in 50..10000");
            }
            // the picture is always a PNG: a file named otherwise would hold one under a name that says it is not
            if (!out.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".png")) {
                throw new UserError("--out " + out + ": world render writes a PNG; give the file a .png name");
            }
            System.setProperty("java.awt.headless", "true");
            SimWorld world = load(file);
            OutPlace.file("--out", out); // before the simulated seconds
            Wander wander = new Wander();
            while (world.time() < seconds) {
                wander.accept(world);
                world.step();
            }
            try {
                PngRenderer.write(world, out, size, size + 60);
            } catch (IOException e) {
                throw OutPlace.cannotWrite("--out", out, e);
            }
            PrintWriter o = spec.commandLine().getOut();
            o.printf("wrote %s after %.1f s of simulated time%n", out, world.time());
            o.flush();
            return 0;
        }
    }
}
