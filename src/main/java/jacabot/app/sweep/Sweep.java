package jacabot.app.sweep;

import jacabot.app.console.ConsoleLog;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.RobotAgent;
import jacabot.robot.Experiment;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CompletionService;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorCompletionService;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * Runs many {@link SweepJob}s in one JVM on a pool of threads (one run per thread at a time), with a
 * progress bar. A run's own wall-clock bound stops it at its next control step; a run that does not
 * even reach one (stuck inside a step) is given up {@link #GRACE_S} s after its bound and reported as a
 * hang, its thread left behind (daemon), so the sweep always ends.
 */
public final class Sweep {
    /** How long past its bound a run may stay silent before the sweep gives it up, seconds. */
    static final double GRACE_S = 90;

    private final int jobs;
    private final double seconds;
    private final double wallLimitS;
    private ConsoleLog progress;
    private boolean socket;
    private boolean pipeline;
    private Consumer<SweepRun.Result> onResult = r -> {
    };
    private final Map<Experiment, List<RobotAgent>> agents = new EnumMap<>(Experiment.class);

    /**
     * What a sweep leaves: every outcome (in job order), the wall-clock time it took, the CPU time
     * the whole JVM used meanwhile (NaN where the JVM does not tell) and the machine's load average
     * at the start (NaN where unknown). On a shared machine the CPU figure is the steadier one: the
     * wall clock also counts the other users' turns.
     */
    public record Outcomes(List<RunOutcome> runs, double wallSeconds, int jobs, double cpuSeconds, double loadAtStart) {
        public Outcomes(List<RunOutcome> runs, double wallSeconds, int jobs) {
            this(runs, wallSeconds, jobs, Double.NaN, Double.NaN);
        }

        /** {@return simulated minutes per wall-clock second, all runs together} */
        public double simulatedMinutesPerSecond() {
            double sim = runs.stream().mapToDouble(RunOutcome::simulated).sum();
            return wallSeconds <= 0 ? 0 : sim / 60 / wallSeconds;
        }

        /** {@return simulated minutes per second of CPU time (all the JVM's threads), NaN if unknown} */
        public double simulatedMinutesPerCpuSecond() {
            double sim = runs.stream().mapToDouble(RunOutcome::simulated).sum();
            return cpuSeconds > 0 ? sim / 60 / cpuSeconds : Double.NaN;
        }
    }

    /** {@return the CPU time of this JVM so far in seconds, NaN when it cannot be read} */
    static double processCpuSeconds() {
        var os = ManagementFactory.getOperatingSystemMXBean();
        if (os instanceof com.sun.management.OperatingSystemMXBean sun) {
            long ns = sun.getProcessCpuTime();
            return ns < 0 ? Double.NaN : ns / 1e9;
        }
        return Double.NaN;
    }

    /**
     * @param jobs       runs at once (threads)
     * @param seconds    simulated seconds per run
     * @param wallLimitS wall-clock bound per run
     */
    public Sweep(int jobs, double seconds, double wallLimitS) {
        if (jobs < 1 || !(seconds > 0) || !(wallLimitS > 0)) {
            throw new IllegalArgumentException("jobs >= 1, seconds > 0 and a positive wall-clock bound needed");
        }
        this.jobs = jobs;
        this.seconds = seconds;
        this.wallLimitS = wallLimitS;
    }

    /** Draws a progress bar through this console (in place on stderr, not with --quiet), or nothing when null. */
    public Sweep progress(ConsoleLog console) {
        this.progress = console;
        return this;
    }

    /** Called with each finished run (on the sweep's thread), e.g. to write its logs. */
    public Sweep onResult(Consumer<SweepRun.Result> listener) {
        this.onResult = listener;
        return this;
    }

    /** Agent runs talk over a loopback socket, as single runs do, instead of the in-process link (the same logs, slower). */
    public Sweep socket(boolean on) {
        this.socket = on;
        return this;
    }

    /** Agent runs in a pipelined lockstep ({@link LockstepRun#pipeline}): their commands one control step later. */
    public Sweep pipeline(boolean on) {
        this.pipeline = on;
        return this;
    }

    /** Runs {@code agent} as the agent of experiment {@code e}, not the packaged one. */
    public Sweep agent(Experiment e, AgentSource agent) {
        return agents(e, List.of(new RobotAgent(RobotAgent.ALONE, agent)));
    }

    /** Runs experiment {@code e}'s robot programmed by these agents (the thesis' Chapter 6 wish), not the packaged one. */
    public Sweep agents(Experiment e, List<RobotAgent> robotAgents) {
        agents.put(e, List.copyOf(robotAgents));
        return this;
    }

    /** Runs the jobs; {@return the outcomes in job order} */
    public Outcomes run(List<SweepJob> list) throws InterruptedException {
        long start = System.nanoTime();
        double cpuStart = processCpuSeconds();
        double load = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
        AtomicInteger threadNo = new AtomicInteger();
        ExecutorService pool = Executors.newFixedThreadPool(jobs, r -> {
            Thread t = new Thread(r, "sweep-" + threadNo.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        CompletionService<Integer> done = new ExecutorCompletionService<>(pool);
        Map<Integer, Long> started = new ConcurrentHashMap<>();
        RunOutcome[] outcomes = new RunOutcome[list.size()];
        Map<Future<Integer>, Integer> futures = new HashMap<>();
        for (int i = 0; i < list.size(); i++) {
            int index = i;
            futures.put(done.submit(() -> {
                started.put(index, System.nanoTime());
                SweepJob job = list.get(index);
                List<RobotAgent> given = agents.get(job.experiment()); // read only once the jobs run
                SweepRun.Result r = SweepRun.run(job, seconds, wallLimitS, given != null ? given
                        : List.of(new RobotAgent(RobotAgent.ALONE, SweepRun.packaged(job.experiment()))), socket, pipeline);
                synchronized (outcomes) {
                    if (outcomes[index] == null) {
                        outcomes[index] = r.outcome();
                        onResult.accept(r);
                    }
                }
                return index;
            }), i);
        }
        int finished = 0, failed = 0;
        double simulated = 0;
        draw(0, list.size(), 0, 0, start);
        try {
            while (finished < list.size()) {
                Future<Integer> f = done.poll(1, TimeUnit.SECONDS);
                if (f != null) {
                    int index;
                    try {
                        index = f.get();
                    } catch (ExecutionException e) {
                        // SweepRun reports every failure in its outcome; this is a bug in the sweep itself
                        index = futures.get(f);
                        synchronized (outcomes) {
                            if (outcomes[index] == null) {
                                outcomes[index] = failure(list.get(index), RunOutcome.CRASH, SweepRun.describe(e.getCause()));
                            }
                        }
                    }
                    futures.remove(f);
                    synchronized (outcomes) {
                        finished = count(outcomes);
                    }
                } else {
                    long now = System.nanoTime();
                    for (Map.Entry<Integer, Long> s : started.entrySet()) {
                        if (now - s.getValue() > (long) ((wallLimitS + GRACE_S) * 1e9)) {
                            synchronized (outcomes) {
                                if (outcomes[s.getKey()] == null) {
                                    outcomes[s.getKey()] = failure(list.get(s.getKey()), RunOutcome.HANG,
                                            String.format(Locale.ROOT, "stuck: no control step for %.0f s past its bound", GRACE_S));
                                }
                            }
                        }
                    }
                    synchronized (outcomes) {
                        finished = count(outcomes);
                    }
                }
                synchronized (outcomes) {
                    failed = 0;
                    simulated = 0;
                    for (RunOutcome o : outcomes) {
                        if (o != null) {
                            failed += o.success() ? 0 : 1;
                            simulated += o.simulated();
                        }
                    }
                }
                draw(finished, list.size(), failed, simulated, start);
            }
        } finally {
            pool.shutdownNow();
            if (progress != null) {
                progress.endInPlace();
            }
        }
        List<RunOutcome> all;
        synchronized (outcomes) {
            all = new ArrayList<>(List.of(outcomes));
        }
        return new Outcomes(all, (System.nanoTime() - start) / 1e9, jobs, processCpuSeconds() - cpuStart, load < 0 ? Double.NaN : load);
    }

    private static int count(RunOutcome[] outcomes) {
        int n = 0;
        for (RunOutcome o : outcomes) {
            n += o == null ? 0 : 1;
        }
        return n;
    }

    private RunOutcome failure(SweepJob job, String status, String message) {
        var f = new SuccessCriteria.Figures(0, 0, 0, 0, 0, 0, false, 0, 0);
        return new RunOutcome(job.experiment(), job.world(), job.controller(), job.seed(), status, false,
                status + ": " + message, 0, wallLimitS + GRACE_S, f, Double.NaN, 0);
    }

    private void draw(int finished, int total, int failed, double simulated, long start) {
        if (progress == null) {
            return;
        }
        double wall = (System.nanoTime() - start) / 1e9;
        int width = 30;
        int full = total == 0 ? width : finished * width / total;
        String eta = finished == 0 ? "?" : format(wall / finished * (total - finished));
        progress.inPlace(String.format(Locale.ROOT, "[%s%s] %d/%d runs, %d failed, %.1f sim-min/s, %s elapsed, ETA %s   ",
                "#".repeat(full), ".".repeat(width - full), finished, total, failed, wall > 0 ? simulated / 60 / wall : 0,
                format(wall), eta));
    }

    private static String format(double s) {
        long t = Math.round(s);
        return t >= 3600 ? String.format(Locale.ROOT, "%dh%02dm", t / 3600, t / 60 % 60)
                : String.format(Locale.ROOT, "%dm%02ds", t / 60, t % 60);
    }

    /** The order of reports: experiment, world, controller, seed. */
    public static final Comparator<RunOutcome> ORDER = Comparator.comparing((RunOutcome o) -> o.experiment().ordinal())
            .thenComparing(RunOutcome::world).thenComparing(RunOutcome::controller).thenComparingLong(RunOutcome::seed);
}
