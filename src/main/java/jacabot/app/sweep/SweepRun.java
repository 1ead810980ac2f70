package jacabot.app.sweep;

import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.RobotAgent;
import jacabot.app.world.Landmarks;
import jacabot.robot.Experiment;
import jacabot.robot.baseline.BaselineController;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.world.WorldSpec;
import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

/**
 * Makes one {@link SweepJob}: loads nothing (the job holds the checked world), builds a fresh world
 * under the job's seed, runs the agent in lockstep ({@link LockstepRun}) or the baseline
 * ({@link BaselineRunner#create}) for the duration, and judges it with {@link SuccessCriteria}.
 * Everything a run uses is its own (world, agent platform, link, recorder), so runs can go
 * on any number of threads at once. A run that passes its wall-clock bound is stopped at its next
 * control step and reported as a hang; an exception is a crash; a run short of its duration an early end.
 */
public final class SweepRun {
    /** What a run leaves: the outcome, the recorder's event log, the last console lines. */
    public record Result(RunOutcome outcome, String eventLog, List<String> consoleTail) {
    }

    private static final Map<Experiment, AgentSource> PACKAGED = new ConcurrentHashMap<>();
    private static final int CONSOLE_TAIL = 200;

    private SweepRun() {
    }

    /** {@return the packaged agent of an experiment, read once for all runs} */
    public static AgentSource packaged(Experiment e) {
        return PACKAGED.computeIfAbsent(e, AgentSource::packaged);
    }

    /** Stops a run from the stepping thread once its wall-clock bound has passed. */
    private static final class Stopped extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Stopped(String message) {
            super(message, null, false, false);
        }
    }

    /**
     * Runs a job.
     *
     * @param seconds     simulated seconds
     * @param wallLimitS  wall-clock bound in seconds
     */
    public static Result run(SweepJob job, double seconds, double wallLimitS) {
        return run(job, seconds, wallLimitS, packaged(job.experiment()));
    }

    /** Runs a job with the given agent (the experiment's packaged one, or a user's), over the in-process link. */
    public static Result run(SweepJob job, double seconds, double wallLimitS, AgentSource agent) {
        return run(job, seconds, wallLimitS, agent, false);
    }

    /**
     * Runs a job with the given agent; an agent run's link is a loopback socket when {@code socket}
     * ({@code jacabot experiment}'s), else the same frames in memory: the same run, to the byte of
     * its logs, without the socket's system calls and thread hand-offs.
     */
    public static Result run(SweepJob job, double seconds, double wallLimitS, AgentSource agent, boolean socket) {
        return run(job, seconds, wallLimitS, List.of(new RobotAgent(RobotAgent.ALONE, agent)), socket);
    }

    /** Runs a job with the robot programmed by the given agents sharing its middleware (the thesis' Chapter 6 wish). */
    public static Result run(SweepJob job, double seconds, double wallLimitS, List<RobotAgent> agents, boolean socket) {
        return run(job, seconds, wallLimitS, agents, socket, false);
    }

    /** As above; with {@code pipeline}, the agent's run is a pipelined lockstep ({@link LockstepRun#pipeline}). */
    public static Result run(SweepJob job, double seconds, double wallLimitS, List<RobotAgent> agents, boolean socket,
            boolean pipeline) {
        long start = System.nanoTime();
        long deadline = start + (long) (wallLimitS * 1e9);
        Experiment e = job.experiment();
        if (job.spec() == null) {
            return new Result(outcome(job, RunOutcome.CRASH, job.problem(), null, null, null, 0, 0), "", List.of());
        }
        var missing = Landmarks.missing(e, job.spec(), job.file() == null ? job.world() : job.file().toString());
        if (missing.isPresent()) {
            return new Result(outcome(job, RunOutcome.CRASH, missing.get(), null, null, null, 0, 0), "", List.of());
        }
        WorldSpec s = job.spec();
        SimWorld world = SimWorld.of(new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), job.seed(),
                s.sensorNoise(), s.walls(), s.boxes(), s.cylinders(), s.storage(), s.charger(), s.robots(), s.events()));
        RunRecorder recorder = RunRecorder.attach(world, e.robot());
        BatteryEpisodes battery = BatteryEpisodes.attach(world, e.robot());
        world.addListener(new WorldListener() {
            @Override
            public void controlStepEnded(long timeMs) {
                if (System.nanoTime() > deadline) {
                    throw new Stopped(String.format(Locale.ROOT, "no end after %.0f s of wall-clock time (at t=%.1f s)",
                            wallLimitS, timeMs / 1000.0));
                }
            }
        });
        ConsoleTail console = new ConsoleTail();
        String status = RunOutcome.OK;
        String message = "";
        try {
            if (job.controller().equals(SweepJob.AGENT)) {
                try (var run = new LockstepRun(world, null, e, agents, job.seed(),
                        new PrintStream(console, true, StandardCharsets.UTF_8)).stepLogs(false).inMemory(!socket).pipeline(pipeline)) {
                    run.runFor(seconds);
                    if (run.agentFailure().isPresent()) {
                        status = RunOutcome.AGENT_FAILURE;
                        message = run.agentFailure().get();
                    }
                }
            } else {
                Consumer<String> note = line -> {
                    recorder.note(line);
                    console.line(line);
                };
                BaselineController c = job.controller().equals(SweepJob.EQUAL) ? BaselineRunner.createEqual(e, world, job.seed(), note)
                        : BaselineRunner.create(e, world, job.seed(), note);
                c.runFor(seconds);
            }
        } catch (Throwable t) {
            Throwable stop = t;
            while (stop != null && !(stop instanceof Stopped)) {
                stop = stop.getCause();
            }
            if (stop != null) {
                status = RunOutcome.HANG;
                message = stop.getMessage();
            } else {
                status = RunOutcome.CRASH;
                message = describe(t);
            }
            if (t instanceof InterruptedException) {
                Thread.currentThread().interrupt();
            }
        }
        double wall = (System.nanoTime() - start) / 1e9;
        RunSummary summary;
        EndState end;
        synchronized (world) {
            summary = recorder.summary(job.controller());
            end = EndState.of(world.snapshot(), job.experiment().robot());
        }
        if (status.equals(RunOutcome.OK) && summary.duration() < seconds - world.controlStep() / 1000.0) {
            status = RunOutcome.EARLY_END;
            message = String.format(Locale.ROOT, "ended at t=%.1f s of %.0f s", summary.duration(), seconds);
        }
        return new Result(outcome(job, status, message, summary, end, battery.episodes(), seconds, wall),
                summary.eventLog(), console.lines());
    }

    private static RunOutcome outcome(SweepJob job, String status, String message, RunSummary s, EndState end,
            List<BatteryEpisodes.Episode> episodes, double seconds, double wall) {
        SuccessCriteria.Figures f;
        if (s == null) {
            f = new SuccessCriteria.Figures(0, 0, 0, 0, 0, 0, false, 0, 0);
        } else {
            // only suspend/resume has a charger to go to and counts its episodes
            boolean counted = job.experiment() == Experiment.SUSPEND_RESUME;
            int completed = counted ? (int) episodes.stream().filter(BatteryEpisodes.Episode::completed).count() : 0;
            f = new SuccessCriteria.Figures(s.duration(), s.contactTime(), s.coverage(), s.picks(), s.deliveries(),
                    s.storageEntriesEmpty(), s.batteryEmptied(), counted ? SuccessCriteria.episodesDue(episodes, s.duration()) : 0,
                    completed, end == null ? 0 : end.cylinders(), end == null ? 0 : end.stored(), end != null && end.parked());
        }
        SuccessCriteria.Verdict v = SuccessCriteria.judge(job.experiment(), f, PhysicalBounds.of(job.experiment(), job.spec()));
        List<String> reasons = new ArrayList<>();
        if (!status.equals(RunOutcome.OK)) {
            reasons.add(status + ": " + message);
        }
        if (status.equals(RunOutcome.OK)) { // a cut-short run's figures are partial: its status is the reason
            reasons.addAll(v.reasons());
        }
        boolean success = status.equals(RunOutcome.OK) && v.success();
        return new RunOutcome(job.experiment(), job.world(), job.controller(), job.seed(), status, success,
                String.join("; ", reasons), s == null ? 0 : s.duration(), wall, f,
                s == null || s.batteryMin() == null ? Double.NaN : s.batteryMin(), s == null ? 0 : s.lost());
    }

    /** One line: the exception and where it arose in our code. */
    public static String describe(Throwable t) {
        Throwable root = t;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        String where = "";
        for (StackTraceElement el : root.getStackTrace()) {
            if (el.getClassName().startsWith("jacabot.")) {
                where = " at " + el.getClassName().substring(el.getClassName().lastIndexOf('.') + 1) + "." + el.getMethodName()
                        + ":" + el.getLineNumber();
                break;
            }
        }
        String text = root.getClass().getSimpleName() + (root.getMessage() == null ? "" : ": " + root.getMessage()) + where;
        return text.replace('\n', ' ').replace('\r', ' ');
    }

    /** The agent's console, keeping the last lines only (for failure reports). */
    private static final class ConsoleTail extends OutputStream {
        private final Deque<String> lines = new ArrayDeque<>();
        private final ByteArrayOutputStream buf = new ByteArrayOutputStream();

        @Override
        public synchronized void write(int b) {
            if (b == '\n') {
                line(buf.toString(StandardCharsets.UTF_8));
                buf.reset();
            } else {
                buf.write(b);
            }
        }

        synchronized void line(String text) {
            lines.addLast(text);
            if (lines.size() > CONSOLE_TAIL) {
                lines.removeFirst();
            }
        }

        synchronized List<String> lines() {
            return List.copyOf(lines);
        }
    }
}
