package jacabot.experiments.bench;

import jacabot.experiments.run.Experiment;
import jacabot.experiments.run.LockstepRun;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.sim.SimWorld;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
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
    private final Path root;
    private final double seconds;
    private final long seed;
    private final PrintStream out;

    public SimulationBenchmark(Path root, double seconds, long seed, PrintStream out) {
        this.root = root;
        this.seconds = seconds;
        this.seed = seed;
        this.out = out;
    }

    public void run() throws Exception {
        Experiment e = Experiment.SUSPEND_RESUME;
        Path world = root.resolve(e.worldFile());
        String source;
        try (InputStream in = SimulationBenchmark.class.getResourceAsStream(e.agentResource())) {
            source = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        // warm-up run, not measured
        runAgent(world, source, Math.min(60, seconds));
        long t0 = System.nanoTime();
        LockstepRun run = runAgent(world, source, seconds);
        long wall = System.nanoTime() - t0;
        long[] sim = run.world().stepCost();
        long[] agent = run.agentSideCost();
        long rest = wall - sim[0] - sim[1] - agent[0] - agent[1];
        out.printf(Locale.ROOT, "Experiment 4 with the agent, lockstep, %.0f s simulated in %.2f s: %.0fx real time, %d reasoning cycles%n",
                seconds, wall / 1e9, seconds / (wall / 1e9), run.cycles());
        out.println("| part | wall time (s) | share |");
        out.println("|---|---|---|");
        row("physics (dyn4j)", sim[0], wall);
        row("devices (sensors, camera, gripper, battery)", sim[1], wall);
        row("artifact (middleware steps)", agent[0], wall);
        row("reasoning (agent cycles)", agent[1], wall);
        row("link: sampling, serialization, socket, thread hand-offs", rest, wall);
        long b0 = System.nanoTime();
        var baseline = BaselineRunner.execute(world, e.baseline(), seed, seconds);
        long bwall = System.nanoTime() - b0;
        long[] bsim = baseline.world().stepCost();
        out.printf(Locale.ROOT, "%nThe procedural baseline on the same world: %.2f s, %.0fx real time "
                + "(physics %.0f%%, devices %.0f%%, controller %.0f%%)%n", bwall / 1e9, seconds / (bwall / 1e9),
                100.0 * bsim[0] / bwall, 100.0 * bsim[1] / bwall, 100.0 * (bwall - bsim[0] - bsim[1]) / bwall);
    }

    private void row(String part, long nanos, long wall) {
        out.printf(Locale.ROOT, "| %s | %.2f | %.0f%% |%n", part, nanos / 1e9, 100.0 * nanos / wall);
    }

    private LockstepRun runAgent(Path world, String source, double duration) throws Exception {
        SimWorld simWorld = BaselineRunner.load(world, seed);
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        var run = new LockstepRun(simWorld, null, Experiment.SUSPEND_RESUME, source, "suspend-resume.asl", seed, quiet);
        run.stepLogs(false).runFor(duration); // the per-step text logs are for replays, not part of a run's cost
        return run;
    }
}
