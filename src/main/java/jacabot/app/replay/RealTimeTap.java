package jacabot.app.replay;

import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.MindWatch;
import jacabot.app.run.LagMeter;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldSnapshot;
import jacabot.sim.robot.Robot;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

/**
 * The step log of a real-time (viewer) run. There the controller and the agent run on their own
 * threads, so the step is taken from the controller's event log: its readings line and its pose
 * line (which ends the step, on the simulation thread, world lock held), with the commands applied
 * since the step before (in real time on the controller's receiving thread, as they arrive),
 * and the mind from the agent's latest sample ({@link MindWatch#sampleEvery}):
 * a step carries a mind change only when a new sample came.
 */
public final class RealTimeTap implements Closeable {
    private final SimWorld world;
    private final Robot robot;
    private final StepLog.Writer log;
    private final AtomicReference<MindState> sampled = new AtomicReference<>();
    private long timeMs = -1;
    private List<String> readings = List.of();
    private final List<String> applied = new ArrayList<>();
    private final Queue<StepLog.Lag> lags = new ConcurrentLinkedQueue<>();
    private IOException failure;
    private boolean closed;

    private final Path file;
    private final StepLog.Header header;

    private RealTimeTap(SimWorld world, StepLog.Writer log, Path file, StepLog.Header header) {
        this.world = world;
        this.robot = world.robots().get(0);
        this.log = log;
        this.file = file;
        this.header = header;
    }

    /** Shows the run in {@code inspector} (if not null): its world, and its whole past from the step log. */
    public void inspect(Inspector inspector) {
        if (inspector != null) {
            inspector.world(header.start());
            RunTap.archive(inspector, log, file, header);
        }
    }

    /** Opens {@code outDir}/{@value StepLog#FILE} for a run of {@code world}; call before it starts. */
    public static RealTimeTap open(SimWorld world, Path outDir, Experiment experiment, String agentFile) throws IOException {
        WorldSnapshot start = world.snapshot();
        var header = new StepLog.Header(StepLog.FORMAT, experiment.id(), world.name(), world.seed(), world.controlStep(),
                world.robots().get(0).name(), agentFile, start, null, StepLog.Header.REAL_TIME);
        var log = new StepLog.Writer(outDir.resolve(StepLog.FILE), header);
        return new RealTimeTap(world, log, outDir.resolve(StepLog.FILE), header);
    }

    /** {@return where the agent's sampled minds go (on the agent's thread)} */
    public Consumer<MindState> minds() {
        return sampled::set;
    }

    /** {@return where the run's lag episodes go: each start and end is written with the next step (any thread)} */
    public LagMeter.Listener lags() {
        return new LagMeter.Listener() {
            @Override
            public void started(LagMeter.Reading r) {
                lags.add(new StepLog.Lag("start", r.worldBehindMs(), r.agentLateMs(), r.requested(), r.achieved()));
            }

            @Override
            public void ended(LagMeter.Episode e) {
                lags.add(new StepLog.Lag("end", e.worstWorldBehindMs(), e.worstAgentLateMs(), e.requested(), e.lowestAchieved()));
            }
        };
    }

    /** {@return the controller's event log sink (on the simulation thread)} */
    public Consumer<String> controllerEvents() {
        return this::event;
    }

    private void event(String line) {
        // "step N t=T KIND=v ...", "step N apply CMD", "step N pose X Z H" (RobotController)
        String[] p = line.split(" ", 4);
        if (p.length < 3 || !p[0].equals("step")) {
            return;
        }
        String rest = p.length > 3 ? p[3] : "";
        if (p[2].startsWith("t=")) {
            timeMs = Long.parseLong(p[2].substring(2));
            readings = rest.isEmpty() ? List.of() : Arrays.asList(rest.split(" "));
        } else if (p[2].equals("apply")) {
            // in real time the controller applies a command as it arrives, on its receiving thread:
            // it goes with the next step written
            synchronized (applied) {
                applied.add(rest);
            }
        } else if (p[2].equals("pose") && timeMs >= 0) {
            write();
        }
    }

    private void write() {
        if (failure != null || closed) {
            return;
        }
        var p = robot.pose();
        var body = new StepLog.Body(p.x(), p.z(), p.heading(), robot.hasBattery() ? robot.getBattery().energy() : null,
                robot.getWheels().getLeftSpeed(), robot.getWheels().getRightSpeed(),
                robot.hasGripper() ? robot.getGripper().heldObject() : null, robot.contactTime());
        List<String> commands;
        synchronized (applied) {
            commands = List.copyOf(applied);
            applied.clear();
        }
        try {
            // two notes in one step (an episode shorter than a step cannot be: the meter looks every 250 ms)
            StepLog.Lag lag = lags.poll();
            log.stepText(timeMs, body, commands, readings, sampled.getAndSet(null), world.supervisor().objects(), lag);
        } catch (UncheckedIOException e) {
            failure = e.getCause(); // a full disk: the run goes on, the log stops
        }
    }

    /**
     * Waits (at most {@code timeoutMs}) until the lag notes given so far are written with a step:
     * call after closing the {@link LagMeter} and before stopping the world, so that
     * an episode open at the end is recorded with its end. {@return whether they were}
     */
    public boolean awaitLagNotes(long timeoutMs) throws InterruptedException {
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        while (!lags.isEmpty() && failure == null && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        return lags.isEmpty();
    }

    /** Closes the log; {@return the error that stopped it early, or null} */
    public IOException closeLog() throws IOException {
        synchronized (world) { // the controller logs with the world's lock held
            closed = true;
            log.close();
        }
        return failure;
    }

    @Override
    public void close() throws IOException {
        closeLog();
    }
}
