package jacabot.app.bench;

import jacabot.robot.Experiment;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepCoordinator;
import jacabot.app.run.LockstepRun;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.sim.SimWorld;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;

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

    /** @param world experiment 4's world file */
    public SimulationBenchmark(Path world, double seconds, long seed, PrintStream out) {
        this.world = world;
        this.seconds = seconds;
        this.seed = seed;
        this.out = out;
    }

    public void run() throws Exception {
        Experiment e = Experiment.SUSPEND_RESUME;
        AgentSource source = AgentSource.packaged(e);
        // Warm-up: a whole run first, so that the measured one runs compiled code rather than
        // sharing the two cores with the JIT compiler (whose C2 threads otherwise take a core for seconds).
        runAgent(world, source, seconds);
        long t0 = System.nanoTime();
        Measured m = runAgent(world, source, seconds);
        long wall = System.nanoTime() - t0;
        long[] sim = m.run().world().stepCost();
        long[] agent = m.run().agentSideCost();
        var c = m.result().controllerCosts();
        var mw = m.result().middlewareCosts();
        long serialization = c.encodingNanos() + mw.decodingNanos();
        long rest = wall - sim[0] - sim[1] - c.samplingNanos() - serialization - c.writingNanos() - agent[0] - agent[1];
        out.printf(Locale.ROOT, "Experiment 4 with the agent, lockstep, seed %d, %.0f s simulated in %.2f s: %.0fx real time; "
                + "%d control steps, %d reasoning cycles, %d artifact steps%n", seed, seconds, wall / 1e9, seconds / (wall / 1e9),
                m.result().steps(), m.run().cycles(), m.run().artifactSteps());
        out.println("| part | wall time (s) | share | per control step (us) |");
        out.println("|---|---|---|---|");
        long steps = Math.max(1, m.result().steps());
        row("physics (dyn4j)", sim[0], wall, steps);
        row("devices (sensors, camera, gripper, battery)", sim[1], wall, steps);
        row("sampling the devices into SensorInfo", c.samplingNanos(), wall, steps);
        row("serialization (ObjectOutputStream, ObjectInputStream)", serialization, wall, steps);
        row("socket writes (the step's frame)", c.writingNanos(), wall, steps);
        row("artifact (middleware steps, operation threads)", agent[0], wall, steps);
        row("reasoning (agent cycles)", agent[1], wall, steps);
        row("waiting: socket and thread wake-ups", rest, wall, steps);
        out.printf(Locale.ROOT, "A control step took %.1f us in all. The agent side's answer writes took %.1f us per step"
                + " (in waiting).%n", wall / 1e3 / steps, mw.writingNanos() / 1e3 / steps);
        if (rest < 0) {
            // a write returns only after waking the reader's thread, which by then is at work on the other core
            out.println("The rows add up to more than the whole: each socket write wakes the other side's thread,"
                    + " whose work overlaps the end of the write.");
        }
        long b0 = System.nanoTime();
        var baseline = BaselineRunner.execute(world, e, seed, seconds);
        long bwall = System.nanoTime() - b0;
        long[] bsim = baseline.world().stepCost();
        out.printf(Locale.ROOT, "%nThe procedural baseline on the same world: %.2f s, %.0fx real time "
                + "(physics %.0f%%, devices %.0f%%, controller %.0f%%)%n", bwall / 1e9, seconds / (bwall / 1e9),
                100.0 * bsim[0] / bwall, 100.0 * bsim[1] / bwall, 100.0 * (bwall - bsim[0] - bsim[1]) / bwall);
    }

    private record Measured(LockstepRun run, LockstepCoordinator.Result result) {
    }

    private void row(String part, long nanos, long wall, long steps) {
        out.printf(Locale.ROOT, "| %s | %.2f | %.0f%% | %.1f |%n", part, nanos / 1e9, 100.0 * nanos / wall, nanos / 1e3 / steps);
    }

    private Measured runAgent(Path world, AgentSource source, double duration) throws Exception {
        SimWorld simWorld = BaselineRunner.load(world, seed);
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        var run = new LockstepRun(simWorld, null, Experiment.SUSPEND_RESUME, source, seed, quiet);
        var result = run.stepLogs(false).runFor(duration); // the per-step text logs are for replays, not part of a run's cost
        return new Measured(run, result);
    }
}
