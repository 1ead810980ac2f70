package jacabot.app.cli;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.app.console.ConsoleLog;
import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.ConsoleRecorder;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindWatch;
import jacabot.app.plot.RunPlots;
import jacabot.app.replay.RealTimeEdits;
import jacabot.app.replay.RealTimeTap;
import jacabot.app.replay.RunTap;
import jacabot.app.replay.StepLog;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LagMeter;
import jacabot.app.run.RealTimeRun;
import jacabot.cartago.CartagoException;
import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import jacabot.sim.viewer.WorldViewer;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

/**
 * {@code jacabot experiment NAME} in real time, the agent running free as in the thesis: the world
 * paced by the simulator, the controller and the middleware on a loopback socket; its step log
 * taken from the controller's event log, its console by simulated time in console.txt. With the
 * Swing viewer, or without it ({@code --real-time --headless}, a server's run) shown by the
 * inspector, whose page can also apply edited plans to the running agent.
 */
final class RealTimeExperiment {
    private final Experiment experiment;
    private final double speed;
    private final int port;
    private final InspectorOptions inspectorOptions;
    private final boolean viewer;
    /** Ctrl-C, SIGTERM or (in-process) an interrupt: the run ends at once and writes what there is. */
    private final AtomicBoolean signalled = new AtomicBoolean();

    /** @param viewer with the Swing viewer (closing it ends the run); without it, the inspector shows the run */
    RealTimeExperiment(Experiment experiment, double speed, int port, InspectorOptions inspectorOptions, boolean viewer) {
        this.viewer = viewer;
        this.experiment = experiment;
        this.speed = speed;
        this.port = port;
        this.inspectorOptions = inspectorOptions;
    }

    /** Runs it; {@return the exit code} @throws RunFailure when the agent failed at its job */
    int run(SimWorld simWorld, Path worldFile, AgentSource source, long runSeed, double seconds,
            ConsoleLog log, Path outDir) throws Exception {
        var done = new CountDownLatch(1);
        ExitHook hook = ExitHook.install("real-time-shutdown", () -> { // Ctrl-C or SIGTERM: end now, write what there is, then let the JVM go
            signalled.set(true);
            try {
                done.await(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        try {
            return runAndWrite(simWorld, worldFile, source, runSeed, seconds, log, outDir);
        } finally {
            done.countDown();
            hook.remove();
        }
    }

    private int runAndWrite(SimWorld simWorld, Path worldFile, AgentSource source, long runSeed, double seconds,
            ConsoleLog log, Path outDir) throws Exception {
        // the step log as in a headless run; its steps come from the controller's event log
        var tap = RealTimeTap.open(simWorld, outDir, experiment, source.name());
        var recorder = RunRecorder.attach(simWorld, simWorld.robots().get(0).name());
        // the agents' console with its simulated times, as a lockstep run's (the event log's lines at each step)
        var consoleFile = ConsoleRecorder.open(outDir, simWorld::timeMs);
        Consumer<String> controllerEvents = tap.controllerEvents().andThen(line -> {
            if (line.contains(" pose ")) { // a step's end, on the simulation thread, the world's lock held
                consoleFile.events(recorder.events());
            }
        });
        long start = System.nanoTime();
        List<LagMeter.Episode> lags = List.of();
        Optional<String> agentFailure = Optional.empty();
        Inspector inspector = null;
        try (var run = new RealTimeRun(simWorld, experiment, source, runSeed, speed, consoleFile.tee(log.agents()),
                port, controllerEvents)) {
            inspector = inspectorOptions.start(true, "experiment " + experiment.id() + ", seed " + runSeed
                    + (viewer ? "" : ", real time"), ConsoleLog.lines(log::result), log::warn);
            tap.inspect(inspector);
            if (inspector != null) {
                inspector.console(ConsoleFile.of(outDir));
                // the page's edited plans, applied at the agent's next reasoning cycle
                inspector.edits(new RealTimeEdits(source, run.mas().agent("robot"), simWorld::timeMs, consoleFile));
            }
            var watches = new ArrayList<MindWatch>();
            for (String name : run.mas().agentNames()) {
                boolean robot = name.equals("robot");
                if (robot || inspector != null) { // the robot's mind also goes to the step log
                    var watch = MindWatch.attach(inspector, run.mas().agent(name),
                            robot ? RunTap.robotView(simWorld) : null);
                    watches.add(robot ? watch.alsoTo(tap.minds()) : watch);
                }
            }
            AutoCloseable sampling = MindWatch.sampleEvery(watches, 200);
            run.lag().addListener(tap.lags()).addListener(LagMeter.firstWarning(log::warn));
            run.start(seconds);
            var closed = new CountDownLatch(1);
            if (viewer) {
                SwingUtilities.invokeLater(() -> {
                    JFrame frame = WorldViewer.open(run.runner(), run.lag()::status);
                    frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
                    frame.addWindowListener(new WindowAdapter() {
                        @Override
                        public void windowClosed(WindowEvent e) {
                            closed.countDown();
                        }
                    });
                });
            } else {
                run.runner().start(); // the world paced in real time on its own thread, as the viewer does
            }
            try {
                while (!closed.await(200, TimeUnit.MILLISECONDS) && !signalled.get()) {
                    if (simWorld.time() >= seconds || run.agentFailure().isPresent()) {
                        break;
                    }
                }
            } catch (InterruptedException e) {
                signalled.set(true); // the launcher's thread interrupted (in-process, as Ctrl-C): end as on a signal
            }
            agentFailure = run.agentFailure();
            run.lag().close(); // an episode still open ends here, and is written with the next step
            tap.awaitLagNotes(1000);
            run.runner().stop();
            sampling.close();
            lags = run.lag().episodes();
            var failure = tap.closeLog();
            if (failure != null) {
                log.warn("the step log " + outDir.resolve(StepLog.FILE) + " stopped early: " + failure.getMessage());
            }
        } catch (AslSyntaxException e) {
            tap.close();
            throw UserError.located(e.getMessage());
        } catch (CartagoException e) {
            tap.close();
            throw new IllegalStateException("cannot make the middleware: " + e.getMessage()
                    + (port != 0 ? "; is port " + port + " free? choose another with --port" : ""), e);
        } finally {
            consoleFile.close(log::warn);
            if (inspector != null && (viewer || signalled.get())) {
                inspector.close();
            }
        }
        log.result(String.format(signalled.get() ? "Stopped by a signal at t=%.1f s of simulated time; writing what there is."
                : "Stopped at t=%.1f s of simulated time.", simWorld.time()));
        recorder.detach();
        ExperimentCommand.report(log, recorder.summary("agent"), simWorld, outDir, (System.nanoTime() - start) / 1e9, -1,
                ExperimentCommand.files(worldFile, source.name()));
        if (!lags.isEmpty()) {
            var text = new StringBuilder(lagSummary(lags, simWorld.time())).append('\n');
            lags.forEach(e -> text.append("  ").append(e.describe()).append('\n'));
            text.toString().lines().forEach(log::result);
            Files.writeString(outDir.resolve("summary.txt"), text, StandardOpenOption.APPEND);
        }
        log.result("Step log: " + outDir.resolve(StepLog.FILE) + " (jacabot replay " + outDir + ")");
        if (signalled.get()) { // the JVM is going: drawing could start what a shutdown refuses (AWT, temporary files)
            log.result("Plots: not drawn after a signal; draw them with: jacabot plot " + outDir);
        } else {
            RunPlots.writeAll(outDir, ConsoleLog.lines(log::result));
        }
        if (inspector != null && !viewer && !signalled.get()) { // a headless run's page stays while asked for
            inspector.showPlots(outDir);
            inspectorOptions.linger(inspector, ConsoleLog.lines(log::result));
            inspector.close();
        }
        if (agentFailure.isPresent()) {
            throw new RunFailure(agentFailure.get());
        }
        return 0;
    }

    static String lagSummary(List<LagMeter.Episode> lags, double simulatedSeconds) {
        long ms = lags.stream().mapToLong(e -> e.endMs() - e.startMs()).sum();
        return String.format(Locale.ROOT, "Lagged behind real time: %d episode%s, %.1f s of %.1f s simulated:",
                lags.size(), lags.size() == 1 ? "" : "s", ms / 1000.0, simulatedSeconds);
    }
}
