package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.run.AgentMetrics;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.experiments.link.LatencyStats;
import jacabot.robot.Experiment;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.robot.baseline.CodeMetrics;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code jacabot compare}: the thesis' Chapter 5 comparison, reproduced. Each experiment runs with
 * the agent and with the procedural baseline on the same world and seeds; the table shows what each
 * achieved and how much code (and how many tests or plans) each needed.
 */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = "Runs each experiment with the agent and with the procedural baseline on the same worlds and "
                + "seeds, and prints the Chapter 5 comparison as a Markdown table.")
final class CompareCommand implements Callable<Integer> {
    @Option(names = "--seeds", split = ",", paramLabel = "N,...", description = "seeds (default ${DEFAULT-VALUE})")
    private List<Long> seeds = List.of(1L, 2L);

    @Option(names = "--duration", paramLabel = "T", description = "simulated time per run (default ${DEFAULT-VALUE})")
    private String duration = "5m";

    @Option(names = "--root", paramLabel = "DIR",
            description = "a repository to take worlds/ and the baselines' sources from (default: the installation's)")
    private Path root;

    @Option(names = "--code-only", description = "only the code tables (no runs): the metrics and what each experiment adds to the previous one")
    private boolean codeOnly;

    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        double seconds = ExperimentCommand.duration(duration);
        var out = ConsoleStreams.of(spec.commandLine().getOut());
        if (codeOnly) {
            codeTables(out);
            return 0;
        }
        out.println("| experiment | controller | seed | picked | delivered | coverage | contact (s) | lowest battery (J) "
                + "| storage entries without a cylinder | reactive time median / p99 (ms) | response time median / p99 (ms) |");
        out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        for (Experiment e : Experiment.thesis()) {
            Path world = bundled(root, e.worldFile());
            for (long seed : seeds) {
                AgentRun a = runAgent(e, world, seed, seconds);
                out.println(row(e, "agent", seed, a.summary) + " " + ms(a.reactive) + " | " + ms(a.response) + " |");
                out.println(row(e, "baseline", seed, BaselineRunner.run(world, e, seed, seconds))
                        + " same step | same step |");
            }
        }
        out.println();
        out.println("Reactive time: from a control step's readings reaching the middleware to the first plan they "
                + "trigger. Response time: from the command leaving the middleware to the controller applying it. "
                + "Both wall clock, in lockstep on this machine. The baseline polls, decides and commands within one step.");
        out.println();
        codeTables(out);
        return 0;
    }

    /** The code metrics of each experiment, then what each adds to the one before (Chapter 5 §2: "new plans and/or beliefs"). */
    private void codeTables(PrintStream out) throws Exception {
        out.println("| experiment | baseline: code lines | `if`s | loops | conditions | agent: code lines | plans | plans with a context | context conditions | coordination beliefs |");
        out.println("|---|---|---|---|---|---|---|---|---|---|");
        for (Experiment e : Experiment.thesis()) {
            CodeMetrics c = CodeMetrics.of(e, root != null ? CodeMetrics.sourceDir(root)
                    : Installation.resolve(CodeMetrics.sourceDir(Path.of("")).toString()));
            AgentMetrics a = AgentMetrics.of(e, AgentSource.packaged(e));
            out.printf(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %d | %d | %d | %d: %s |%n", e, c.codeLines(), c.ifs(),
                    c.loops(), c.conditions(), a.codeLines(), a.plans(), a.contexts(), a.conditions(),
                    a.coordinationBeliefs().size(), String.join(", ", a.coordinationBeliefs()));
        }
        out.println();
        out.println("What each experiment adds to the one before: the agent's skills (included files), plans, code lines and "
                + "coordination beliefs; the baseline's code lines and conditions.");
        out.println();
        out.println("| experiment | agent: skills added | plans | code lines | coordination beliefs added | baseline: code lines | conditions |");
        out.println("|---|---|---|---|---|---|---|");
        AgentMetrics before = null;
        CodeMetrics cBefore = null;
        List<String> skillsBefore = List.of();
        for (Experiment e : Experiment.values()) {
            AgentSource source = AgentSource.packaged(e);
            AgentMetrics a = AgentMetrics.of(e, source);
            List<String> skills = source.sources().stream().skip(1).map(x -> Path.of(x.name()).getFileName().toString()).toList();
            CodeMetrics c = e.hasBaseline() ? CodeMetrics.of(e, baselineDir()) : null;
            var newBeliefs = new TreeSet<>(a.coordinationBeliefs());
            if (before != null) {
                newBeliefs.removeAll(before.coordinationBeliefs());
            }
            var newSkills = new ArrayList<>(skills);
            newSkills.removeAll(skillsBefore);
            out.printf(Locale.ROOT, "| %s | %s | %s | %s | %s | %s | %s |%n", e, String.join(", ", newSkills),
                    delta(a.plans(), before == null ? null : before.plans()),
                    delta(a.codeLines(), before == null ? null : before.codeLines()), String.join(", ", newBeliefs),
                    c == null ? "- (none)" : delta(c.codeLines(), cBefore == null ? null : cBefore.codeLines()),
                    c == null ? "-" : delta(c.conditions(), cBefore == null ? null : cBefore.conditions()));
            before = a;
            skillsBefore = skills;
            if (c != null) {
                cBefore = c;
            }
        }
        fourWayCode(out);
    }

    /**
     * Chapter 5 like for like: the code of the thesis' agent as published and of its C-style baseline,
     * of our agent and of the equal-capability baseline (the same program with the agents' strategies).
     */
    private void fourWayCode(PrintStream out) throws Exception {
        out.println();
        out.println("Four ways (code): the thesis' agent as published, the thesis-style baseline, our agent, the "
                + "equal-capability baseline. Their success on generated worlds: `jacabot sweep` (docs/comparison.md).");
        out.println();
        out.println("| experiment | thesis agent: code lines | plans | thesis baseline: code lines | conditions "
                + "| our agent: code lines | plans | equal baseline: code lines | conditions |");
        out.println("|---|---|---|---|---|---|---|---|---|");
        for (Experiment e : Experiment.thesis()) {
            AgentMetrics thesis = AgentMetrics.of(e, AgentSource.resource("asl/as-published/" + e.id() + ".asl", e.id() + ".asl"));
            AgentMetrics ours = AgentMetrics.of(e, AgentSource.packaged(e));
            CodeMetrics c = CodeMetrics.of(e, baselineDir()), q = CodeMetrics.ofEqual(e, baselineDir());
            out.printf(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %d | %d | %d |%n", e, thesis.codeLines(), thesis.plans(),
                    c.codeLines(), c.conditions(), ours.codeLines(), ours.plans(), q.codeLines(), q.conditions());
        }
    }

    private Path baselineDir() {
        return root != null ? CodeMetrics.sourceDir(root) : Installation.resolve(CodeMetrics.sourceDir(Path.of("")).toString());
    }

    private static String delta(int now, Integer before) {
        return before == null ? String.valueOf(now) : String.format(Locale.ROOT, "%d (%+d)", now, now - before);
    }

    /** {@return a file of the repository: under {@code --root} if given, else the installation's (from any folder)} */
    static Path bundled(Path root, String file) {
        return root != null ? root.resolve(file) : Installation.resolve(file);
    }

    private record AgentRun(RunSummary summary, LatencyStats reactive,
            LatencyStats response) {
    }

    private static AgentRun runAgent(Experiment e, Path world, long seed, double seconds) throws Exception {
        SimWorld simWorld = BaselineRunner.load(world, seed);
        var quiet = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        try (var run = new LockstepRun(simWorld, null, e, AgentSource.packaged(e), seed, quiet)) {
            RunRecorder recorder = RunRecorder.attach(simWorld, e.robot());
            var result = run.runFor(seconds);
            return new AgentRun(recorder.summary("agent"), run.reactiveTimes(), result.response());
        }
    }

    private static String ms(LatencyStats s) {
        return s.count() == 0 ? "-" : String.format(Locale.ROOT, "%.3f / %.3f", s.medianMicros() / 1000.0, s.p99Micros() / 1000.0);
    }

    private static String row(Experiment e, String controller, long seed, RunSummary s) {
        return String.format(Locale.ROOT, "| %s | %s | %d | %d | %d | %.0f%% | %.1f | %s | %d |", e, controller, seed, s.picks(),
                s.deliveries(), 100 * s.coverage(), s.contactTime(),
                s.batteryMin() == null ? "-" : String.format(Locale.ROOT, "%.0f", s.batteryMin()), s.storageEntriesEmpty());
    }
}
