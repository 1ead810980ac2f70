package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.app.world.TeamWorld;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.viewer.WorldViewer;
import jacabot.sim.world.WorldSpec;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code jacabot controller}: the robot controller process on its own (thesis Chapter 4, "Start the
 * Simulation"): runs one robot of a world and connects to the middleware's server socket, so the
 * simulator and the agent platform can run as two processes. With {@code --lockstep} and a world of
 * several robots it runs them all, a team ({@link TeamControllerRun}).
 */
@Command(name = "controller", mixinStandardHelpOptions = true,
        description = {"Runs one robot of a world as a robot controller process: it connects to the middleware "
                + "(retrying until it is up), sends its sensor readings every control step and applies the commands it receives.",
                "Real time (x --speed) by default; --lockstep waits for the agent every step."})
final class ControllerCommand implements Callable<Integer> {
    @Option(names = "--world", required = true, paramLabel = "FILE", description = "the world file, e.g. worlds/navigation.json")
    private Path world;

    @Option(names = "--robot", paramLabel = "NAME", description = "the robot to control (default: the world's first; "
            + "with --lockstep and a world of several robots, every robot: a team)")
    private String robot;

    @Option(names = "--robots", paramLabel = "N", description = "with --lockstep: a team of the world's first N robots, "
            + "robot i connecting to --port + i (default: every robot of the world)")
    private Integer robots;

    @Option(names = "--seed", paramLabel = "N", description = "the world's seed: sensor noise, random motion (default: the world file's)")
    private Long seed;

    @Option(names = "--out", paramLabel = "DIR", description = "a team: write per robot DIR/ROBOT/summary.json and event-log.txt (ground truth)")
    private Path out;

    @Option(names = "--link-log", description = "a team, with --out: also DIR/ROBOT/link-log.txt, a line per reading, applied command and pose")
    private boolean linkLog;

    @Option(names = "--host", paramLabel = "HOST", description = "the middleware's address (default ${DEFAULT-VALUE})")
    private String host = "127.0.0.1";

    @Option(names = "--port", paramLabel = "PORT", description = "the middleware's port (default ${DEFAULT-VALUE})")
    private int port = 4444;

    @Option(names = "--viewer", description = "show the world in a window (pause, step, slower, faster)")
    private boolean viewer;

    @Option(names = "--lockstep", description = "advance the world only when the agent has answered each step")
    private boolean lockstep;

    @Option(names = "--pipeline", description = "with --lockstep, one robot: simulate the next step while the agent "
            + "reasons; its commands take effect one control step later (docs/performance.md section 17)")
    private boolean pipeline;

    @Option(names = "--speed", paramLabel = "X", description = "real time x this factor (default ${DEFAULT-VALUE})")
    private double speed = 1.0;

    @Option(names = "--fail-safe-ms", paramLabel = "MS",
            description = "stop the wheels after this long (wall clock and simulated time) without a command or heartbeat (default ${DEFAULT-VALUE})")
    private long failSafeMs = ControllerConfig.FAIL_SAFE_MS;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "the link secret shared with the middleware (default ~/.jacabot/link-secret, made 0600 if absent)")
    private Path secretFile;

    @Option(names = "--event-log", paramLabel = "FILE",
            description = "write a line per reading, applied command and pose (two lockstep runs of one world and agent give the same file)")
    private Path eventLog;

    @Option(names = "--tls-store", paramLabel = "FILE",
            description = "connect with TLS, trusting the certificates of this key store (PKCS12 or JKS, made with keytool)")
    private Path tlsStore;

    @Option(names = "--tls-password-file", paramLabel = "FILE", description = "the --tls-store's password, on the file's first line")
    private Path tlsPasswordFile;

    @Spec
    private CommandSpec spec;

    @Option(names = "--seconds", paramLabel = "S", description = "stop after this much simulated time (default: run until stopped)")
    private Double seconds;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter stdout = spec.commandLine().getOut();
        ControllerConfig config;
        try {
            config = ControllerConfig.defaults().withAddress(host, port).withRobot(robot).withLockstep(lockstep)
                    .withSpeedFactor(speed).withFailSafeMs(failSafeMs);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        PrintWriter err = spec.commandLine().getErr();
        config = config.withLog(line -> {
            err.println("[controller] " + line);
            err.flush();
        });
        try {
            config = config.withSecret(secretFile != null ? LinkSecret.loadOrCreate(secretFile)
                    : LinkSecret.userDefault());
        } catch (IOException | UncheckedIOException e) {
            throw new UserError(e.getMessage() + (secretFile == null ? " (or pass --secret-file FILE)" : ""));
        }
        if (tlsStore != null) {
            config = config.withTls(TlsOptions.context(tlsStore, tlsPasswordFile));
        } else if (tlsPasswordFile != null) {
            throw new UserError("--tls-password-file goes with --tls-store FILE");
        }
        if (seconds != null && !(seconds > 0 && seconds < 1e9)) {
            throw new UserError("--seconds must be a positive number, got " + seconds);
        }
        if (viewer && GraphicsEnvironment.isHeadless()) {
            throw new UserError("--viewer needs a display, and this Java runs headless");
        }
        WorldSpec spec = spec(); // its own errors are the user's, said as they are
        SimWorld simWorld;
        try {
            simWorld = SimWorld.of(spec);
        } catch (RuntimeException e) {
            throw new UserError(world + ": this world cannot run: " + JacabotCommand.describe(e));
        }
        if (isTeam(simWorld)) {
            if (pipeline) {
                throw new UserError("--pipeline: a team's controller runs in plain lockstep only");
            }
            if (eventLog != null) {
                throw new UserError("--event-log: a team's controller writes each robot's link log to OUT/ROBOT/link-log.txt; use --out DIR --link-log");
            }
            if (port + simWorld.robots().size() - 1 > 65535) {
                throw new UserError("--port " + port + ": a team of " + simWorld.robots().size() + " needs ports up to " + (port + simWorld.robots().size() - 1));
            }
            return new TeamControllerRun(simWorld, config, host, port, out, linkLog, stdout).run(seconds);
        }
        if (out != null || linkLog) {
            throw new UserError((out != null ? "--out" : "--link-log") + " is for a team (--lockstep and a world of several robots); "
                    + "one robot's controller writes its link log with --event-log FILE");
        }
        BufferedWriter events = null;
        if (eventLog != null) {
            try {
                events = Files.newBufferedWriter(eventLog, StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw OutPlace.cannotWrite("--event-log", eventLog, e);
            }
            config = config.withEventLog(LineSink.into(events));
        }
        if (pipeline && !lockstep) {
            throw new UserError("--pipeline goes with --lockstep");
        }
        RobotController controller;
        try {
            controller = new RobotController(simWorld, config).pipelined(pipeline);
        } catch (IllegalArgumentException e) {
            throw new UserError(world + ": " + e.getMessage());
        }
        stdout.println(String.format(Locale.ROOT, "controller: robot '%s' (%s) of world '%s', %s; middleware at %s:%d",
                controller.robot().name(), controller.robot().model().name(), simWorld.name(),
                lockstep ? (pipeline ? "pipelined lockstep" : "lockstep") : "real time x" + speed, host, port) + (tlsStore != null ? " over TLS" : ""));
        final BufferedWriter eventsFile = events;
        ExitHook hook = ExitHook.install("controller-shutdown", () -> {
            controller.close();
            closeQuietly(eventsFile);
        });
        try {
            controller.start();
            run(controller.runner());
        } finally {
            controller.close();
            closeQuietly(eventsFile);
            controller.runner().stop();
            hook.remove();
        }
        stdout.println(String.format(Locale.ROOT, "controller: stopped at t=%.2f s after %d steps",
                simWorld.time(), controller.steps()));
        stdout.flush();
        return 0;
    }

    /** {@return the world file's spec, with --seed and the first --robots robots} */
    private WorldSpec spec() {
        WorldSpec spec;
        Path file = Installation.locate(world);
        try {
            spec = WorldFileReader.read(file);
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
        if (seed != null) {
            spec = TeamDeliveryRun.withSeed(spec, seed);
        }
        if (robots != null) {
            if (robot != null) {
                throw new UserError("--robots N makes a team, --robot NAME runs one robot: choose one");
            }
            if (robots < 1 || robots > spec.robots().size()) {
                throw new UserError("--robots must be in 1.." + spec.robots().size() + " (the robots of " + Installation.shown(file)
                        + "), got " + robots);
            }
            spec = TeamWorld.firstRobots(spec, robots);
        }
        return spec;
    }

    /** A team: lockstep, no --robot, and --robots or a world of several robots. */
    private boolean isTeam(SimWorld w) {
        boolean team = robot == null && (robots != null || w.robots().size() > 1);
        if (team && !lockstep) {
            throw new UserError("a team (" + w.robots().size() + " robots in " + world + ") runs in lockstep only: add --lockstep, "
                    + "or choose one robot with --robot NAME");
        }
        if (team && (viewer || tlsStore != null)) {
            throw new UserError("a team's controller runs headless and without TLS (not built): drop " + (viewer ? "--viewer" : "--tls-store"));
        }
        return team;
    }

    private static void closeQuietly(Writer w) {
        if (w != null) {
            try {
                w.close();
            } catch (IOException e) {
                // the run is over; nothing more to say
            }
        }
    }

    private void run(SimRunner runner) throws InterruptedException {
        if (viewer) {
            CountDownLatch closed = new CountDownLatch(1);
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
            closed.await();
        } else if (seconds != null) {
            runner.runFor(seconds);
        } else {
            runner.start();
            new CountDownLatch(1).await(); // until Ctrl-C: the shutdown hook says goodbye
        }
    }
}
