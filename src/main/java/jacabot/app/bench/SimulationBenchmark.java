package jacabot.app.bench;

import com.sun.management.OperatingSystemMXBean;
import jacabot.robot.Experiment;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepCoordinator;
import jacabot.app.run.LockstepRun;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.sim.SimWorld;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.function.ToLongFunction;
import java.util.stream.Collectors;

/**
 * Experiment 4 headless in lockstep with the agent in the loop (agent, artifact, socket,
 * controller, physics, sensors): the real-time factor and where the wall time goes; then the same
 * world with the procedural baseline, to show what the agent layers cost.
 */
public final class SimulationBenchmark {
    private final Path world;
    private final double seconds;
    private final long seed;
    private final PrintStream out;
    private final int warmups;
    private final int measuredRuns;
    private final boolean turns;
    private boolean pipeline;
    /** Warm-up runs at most: more than {@link #warmups} while the JIT has not settled ({@link #settleWithin}). */
    private int maxWarmups;
    /** The process's CPU time: on a loaded machine it tells what a run costs where its wall time does not. */
    private final OperatingSystemMXBean os = (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

    /**
     * @param world        experiment 4's world file
     * @param warmups      whole unmeasured runs first
     * @param measuredRuns measured runs; the median one is reported
     */
    public SimulationBenchmark(Path world, double seconds, long seed, int warmups, int measuredRuns, PrintStream out) {
        this(world, seconds, seed, warmups, measuredRuns, false, out);
    }

    /** @param turns the simulation thread takes the middleware's turns ({@link LockstepRun#takeTurns}) */
    public SimulationBenchmark(Path world, double seconds, long seed, int warmups, int measuredRuns, boolean turns,
            PrintStream out) {
        BenchRuns.check(warmups, measuredRuns);
        this.world = world;
        this.seconds = seconds;
        this.seed = seed;
        this.warmups = warmups;
        this.measuredRuns = measuredRuns;
        this.turns = turns;
        this.out = out;
        this.maxWarmups = warmups;
    }

    /**
     * The JIT has settled after two warm-up runs in a row in which its compilers took at most this
     * share of the process's CPU: measured runs before that pay for compiling on the cores the
     * run's two threads take turns on, and for code not compiled yet (docs/performance.md §25:
     * after four warm-up runs the compilers still took 40–47 % of the measured runs' CPU).
     */
    static final double SETTLED_JIT_SHARE = 0.10;

    /**
     * Warms up past the {@code warmups} runs, up to {@code max} runs in all, until the JIT has
     * settled ({@link #SETTLED_JIT_SHARE}); with {@code max} at most {@code warmups} (the
     * constructor's default), or where the compilers' CPU cannot be read, exactly {@code warmups}. {@return this}
     */
    public SimulationBenchmark settleWithin(int max) {
        this.maxWarmups = Math.max(warmups, max);
        return this;
    }

    /**
     * Also measures the pipelined lockstep ({@link LockstepRun#pipeline}), each of its runs after one
     * of the plain lockstep's, and prints it beside them. {@return this}
     */
    public SimulationBenchmark pipeline(boolean on) {
        this.pipeline = on;
        return this;
    }

    public void run() throws Exception {
        Experiment e = Experiment.SUSPEND_RESUME;
        AgentSource source = AgentSource.packaged(e);
        // Warm-up: whole runs first, so that the measured ones run compiled code. On two cores the
        // JIT compiler shares the machine with the run's thread, and one run is not enough for it
        // to finish: in runs of 10 simulated minutes the speed keeps rising until about the fourth.
        List<String> warm = new ArrayList<>();
        List<String> jitShares = new ArrayList<>();
        boolean settled = false;
        int quietRuns = 0; // in a row: one run under the share may be a lull in C2's queue
        for (int i = 0; i < warmups || (i < maxWarmups && !settled); i++) {
            long cpu0 = os.getProcessCpuTime();
            long jit0 = CompilerThreads.cpuNanos();
            long w0 = System.nanoTime();
            runAgent(world, source, seconds, false);
            warm.add(factor(System.nanoTime() - w0));
            long jit = jit0 < 0 ? -1 : CompilerThreads.cpuNanos() - jit0;
            long cpu = os.getProcessCpuTime() - cpu0;
            if (jit < 0 || cpu <= 0) {
                settled = true; // not measurable here: the fixed count
            } else {
                jitShares.add(String.format(Locale.ROOT, "%.0f%%", 100.0 * jit / cpu));
                quietRuns = jit <= SETTLED_JIT_SHARE * cpu ? quietRuns + 1 : 0;
                settled = quietRuns >= 2;
            }
            if (pipeline) {
                runAgent(world, source, seconds, true);
            }
        }
        List<Measured> runs = new ArrayList<>();
        List<Measured> pipelined = new ArrayList<>();
        for (int i = 0; i < measuredRuns; i++) {
            runs.add(measure(source, false));
            if (pipeline) {
                pipelined.add(measure(source, true));
            }
        }
        Measured m = median(runs, Measured::wall); // runs vary with the JIT's progress and the machine's load
        long wall = m.wall();
        long[] sim = m.run().world().stepCost();
        long[] agent = m.run().agentSideCost();
        var c = m.result().controllerCosts();
        var mw = m.result().middlewareCosts();
        long serialization = c.encodingNanos() + mw.decodingNanos();
        long rest = wall - sim[0] - sim[1] - c.samplingNanos() - serialization - c.writingNanos() - mw.writingNanos()
                - agent[0] - agent[1];
        out.printf(Locale.ROOT, "Experiment 4 with the agent, lockstep, seed %d, %.0f s simulated per run: %d warm-up runs (%s%s), "
                + "then %d measured runs (%s)%n", seed, seconds, warm.size(), String.join(" ", warm),
                jitShares.isEmpty() || maxWarmups <= warmups ? ""
                        : "; the JIT compilers' share of each one's CPU " + String.join(" ", jitShares)
                                + (settled ? "" : ", not settled under " + Math.round(100 * SETTLED_JIT_SHARE) + "% by the last"),
                measuredRuns, runs.stream().map(r -> factor(r.wall())).collect(Collectors.joining(" ")));
        out.printf(Locale.ROOT, "The median run: %.0f s simulated in %.2f s: %.0fx real time; "
                + "%d control steps, %d reasoning cycles, %d artifact steps%n", seconds, wall / 1e9, seconds / (wall / 1e9),
                m.result().steps(), m.run().cycles(), m.run().artifactSteps());
        out.println("| part | wall time (s) | share | per control step (us) |");
        out.println("|---|---|---|---|");
        long steps = Math.max(1, m.result().steps());
        row("physics (dyn4j)", sim[0], wall, steps);
        row("devices (sensors, camera, gripper, battery)", sim[1], wall, steps);
        row("sampling the devices into SensorInfo", c.samplingNanos(), wall, steps);
        row("serialization (the frames' encoding and decoding)", serialization, wall, steps);
        row("socket writes (the step's frame)", c.writingNanos(), wall, steps);
        row("artifact (middleware steps, operation threads)", agent[0], wall, steps);
        row("reasoning (agent cycles)", agent[1], wall, steps);
        row("socket writes (the answer: commands and acknowledgement)", mw.writingNanos(), wall, steps);
        row("the rest: socket reads, the link's bookkeeping, thread wake-ups", rest, wall, steps);
        out.printf(Locale.ROOT, "A control step took %.1f us in all.%n", wall / 1e3 / steps);
        out.println(threads(m));
        if (rest < 0) {
            // a write returns only after waking the reader's thread, which by then is at work on the other core
            out.println("The rows add up to more than the whole: each socket write wakes the other side's thread,"
                    + " whose work overlaps the end of the write.");
        }
        long[] baseline = baseline(e);
        out.printf(Locale.ROOT, "The process's CPU per simulated second, median runs: the agent's %.1f ms, the baseline's %.1f ms.%n",
                m.cpu() / 1e6 / seconds, baseline[1] / 1e6 / seconds);
        out.printf(Locale.ROOT, "The agent's run at %.2f of the baseline's speed (median runs of this invocation; by CPU time %.2f).%n",
                (double) baseline[0] / wall, (double) baseline[1] / m.cpu());
        if (m.jit() >= 0 && baseline[2] >= 0) {
            // compiling and the step's own cost apart: a run still young for the JIT pays for both
            long agentOwn = m.cpu() - m.jit();
            long baselineOwn = baseline[1] - baseline[2];
            out.printf(Locale.ROOT, "Of that CPU the JIT compilers took %.1f ms per simulated second in the agent's run (%.0f%%), "
                    + "%.1f ms in the baseline's (%.0f%%); without them the agent's %.1f ms, the baseline's %.1f ms: "
                    + "by CPU without the JIT %.2f of the baseline's speed.%n",
                    m.jit() / 1e6 / seconds, 100.0 * m.jit() / Math.max(1, m.cpu()), baseline[2] / 1e6 / seconds,
                    100.0 * baseline[2] / Math.max(1, baseline[1]), agentOwn / 1e6 / seconds, baselineOwn / 1e6 / seconds,
                    (double) baselineOwn / Math.max(1, agentOwn));
        }
        if (pipeline) {
            Measured p = median(pipelined, Measured::wall);
            out.printf(Locale.ROOT, "%nThe pipelined lockstep (--pipeline: the world simulates the next step while the agent reasons, "
                    + "its answer applied one control step later), %d measured runs each after one of the above (%s): the median "
                    + "%.2f s, %.0fx real time; %d control steps, %d reasoning cycles%n", measuredRuns,
                    pipelined.stream().map(r -> factor(r.wall())).collect(Collectors.joining(" ")), p.wall() / 1e9,
                    seconds / (p.wall() / 1e9), p.result().steps(), p.run().cycles());
            out.println(threads(p));
            out.printf(Locale.ROOT, "Its process's CPU per simulated second %.1f ms%s; at %.2f of the baseline's speed (by CPU %.2f); "
                    + "against the lockstep's median run: wall %.2fx, CPU %.2fx.%n", p.cpu() / 1e6 / seconds,
                    p.jit() < 0 ? "" : String.format(Locale.ROOT, " (the JIT compilers %.1f ms)", p.jit() / 1e6 / seconds),
                    (double) baseline[0] / p.wall(), (double) baseline[1] / p.cpu(), (double) p.wall() / wall,
                    (double) p.cpu() / Math.max(1, m.cpu()));
        }
    }

    private Measured measure(AgentSource source, boolean pipelined) throws Exception {
        long cpu0 = os.getProcessCpuTime();
        long jit0 = CompilerThreads.cpuNanos();
        long t0 = System.nanoTime();
        Measured m = runAgent(world, source, seconds, pipelined);
        long cpu = os.getProcessCpuTime() - cpu0;
        return m.timed(System.nanoTime() - t0, cpu, jit0 < 0 ? -1 : CompilerThreads.cpuNanos() - jit0);
    }

    /**
     * {@return the two threads' share of a run}: the simulation thread's wait for the agent's answer,
     * and the agent side's own work (decoding, artifact, reasoning, the answer's write). In lockstep
     * they add up to about the whole; pipelined, the world's work hides under the agent's.
     */
    private String threads(Measured m) {
        long steps = Math.max(1, m.result().steps());
        long waited = m.result().controllerCosts().waitingNanos();
        var mw = m.result().middlewareCosts();
        long[] agent = m.run().agentSideCost();
        long agentWork = mw.decodingNanos() + agent[0] + agent[1] + mw.writingNanos();
        String line = String.format(Locale.ROOT, "The simulation thread worked %.2f s (%.0f us a step) and waited for the agent's answer "
                + "%.2f s (%.0f%%, %.0f us a step); the agent's side worked %.2f s (%.0f%%, %.0f us a step).",
                (m.wall() - waited) / 1e9, (m.wall() - waited) / 1e3 / steps, waited / 1e9, 100.0 * waited / m.wall(),
                waited / 1e3 / steps, agentWork / 1e9, 100.0 * agentWork / m.wall(), agentWork / 1e3 / steps);
        long[] cpu = m.run().threadCpuNanos();
        if (cpu[0] < 0 || cpu[1] < 0) {
            return line;
        }
        // what the load does not change: on two free cores a lockstep step costs the sum, a pipelined one at best the larger
        line += String.format(Locale.ROOT, " By their own CPU: the simulation thread %.2f ms, the agent's %.2f ms per "
                + "simulated second; their larger is %.2f of their sum.", cpu[0] / 1e6 / seconds, cpu[1] / 1e6 / seconds,
                (double) Math.max(cpu[0], cpu[1]) / Math.max(1, cpu[0] + cpu[1]));
        if (cpu[2] < 0 || cpu[3] < 0) {
            return line;
        }
        // the kernel's part, which profilers of Java code do not see: over the socket, the link's calls, sleeps and wake-ups
        return line + String.format(Locale.ROOT, " Their system time: %.1f and %.1f us a control step.", cpu[2] / 1e3 / steps,
                cpu[3] / 1e3 / steps);
    }

    /**
     * The procedural baseline, warmed up and measured the same way. {@return its median run's wall time,
     * CPU time and the JIT compilers' CPU time in it (-1 where not known)}
     */
    private long[] baseline(Experiment e) throws Exception {
        for (int i = 0; i < warmups; i++) {
            BaselineRunner.execute(world, e, seed, seconds);
        }
        List<long[]> runs = new ArrayList<>(); // wall, physics, devices, CPU, the JIT's CPU
        for (int i = 0; i < measuredRuns; i++) {
            long cpu0 = os.getProcessCpuTime();
            long jit0 = CompilerThreads.cpuNanos();
            long b0 = System.nanoTime();
            var baseline = BaselineRunner.execute(world, e, seed, seconds);
            long wallNanos = System.nanoTime() - b0;
            long[] bsim = baseline.world().stepCost();
            long jit = jit0 < 0 ? -1 : CompilerThreads.cpuNanos() - jit0;
            runs.add(new long[] {wallNanos, bsim[0], bsim[1], os.getProcessCpuTime() - cpu0, jit});
        }
        String each = runs.stream().map(r -> factor(r[0])).collect(Collectors.joining(" "));
        long[] b = median(runs, r -> r[0]);
        out.printf(Locale.ROOT, "%nThe procedural baseline on the same world, %d measured runs (%s): the median %.2f s, %.0fx real time "
                + "(physics %.0f%%, devices %.0f%%, controller %.0f%%)%n", measuredRuns, each, b[0] / 1e9, seconds / (b[0] / 1e9),
                100.0 * b[1] / b[0], 100.0 * b[2] / b[0], 100.0 * (b[0] - b[1] - b[2]) / b[0]);
        return new long[] {b[0], b[3], b[4]};
    }

    /** {@return the run of median wall time} */
    private static <T> T median(List<T> runs, ToLongFunction<T> wall) {
        List<T> byWall = new ArrayList<>(runs);
        byWall.sort(Comparator.comparingLong(wall));
        return byWall.get(byWall.size() / 2);
    }

    private String factor(long wallNanos) {
        return String.format(Locale.ROOT, "%.0fx", seconds / (wallNanos / 1e9));
    }

    /** @param jit the JIT compilers' CPU time in the run, -1 where not known */
    private record Measured(LockstepRun run, LockstepCoordinator.Result result, long wall, long cpu, long jit) {
        Measured timed(long wallNanos, long cpuNanos, long jitNanos) {
            return new Measured(run, result, wallNanos, cpuNanos, jitNanos);
        }
    }

    private void row(String part, long nanos, long wall, long steps) {
        out.printf(Locale.ROOT, "| %s | %.2f | %.0f%% | %.1f |%n", part, nanos / 1e9, 100.0 * nanos / wall, nanos / 1e3 / steps);
    }

    private Measured runAgent(Path world, AgentSource source, double duration, boolean pipelined) throws Exception {
        SimWorld simWorld = BaselineRunner.load(world, seed);
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        var run = new LockstepRun(simWorld, null, Experiment.SUSPEND_RESUME, source, seed, quiet);
        var result = run.stepLogs(false).takeTurns(turns).pipeline(pipelined).runFor(duration); // the per-step text logs are for replays, not part of a run's cost
        run.close(); // its figures stay readable
        return new Measured(run, result, 0, 0, -1);
    }
}
