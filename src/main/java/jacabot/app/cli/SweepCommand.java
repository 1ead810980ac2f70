package jacabot.app.cli;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.app.Installation;
import jacabot.app.console.ConsoleLog;
import jacabot.app.run.AgentSource;
import jacabot.app.sweep.RunOutcome;
import jacabot.app.sweep.SuccessCriteria;
import jacabot.app.sweep.Sweep;
import jacabot.app.sweep.SweepJob;
import jacabot.app.sweep.SweepPlan;
import jacabot.app.sweep.SweepReport;
import jacabot.app.sweep.SweepRun;
import jacabot.app.world.WorldGenerator.Profile;
import jacabot.robot.Experiment;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.Callable;
import java.util.regex.Pattern;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine;

/**
 * {@code jacabot sweep EXPERIMENT|all}: agent and baseline, headless in lockstep, over every world x
 * seed, many runs in this one JVM; writes runs.csv and report.md. {@code jacabot sweep merge DIR...}
 * joins shards.
 */
@Command(name = "sweep", mixinStandardHelpOptions = true, subcommands = SweepCommand.Merge.class,
        description = {"Runs the agent and the procedural baseline headless in lockstep over every world x seed, on a pool "
                + "of threads in one JVM, and judges each run by the success criteria (docs/comparison.md).",
                "Writes OUT/runs.csv (a row per run), OUT/report.md (a table per experiment), OUT/logs/ (event log of each "
                + "run; the agent's last console lines for failed runs) and, with --generate, OUT/worlds/.",
                "Exit 0 when every run was made (failed runs included), 2 on bad usage."})
final class SweepCommand implements Callable<Integer> {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "EXPERIMENT",
            description = "obstacle-avoidance | object-picking | navigation | suspend-resume | tidy-up | all (the thesis' four)")
    private String experiment;

    @Option(names = "--worlds", paramLabel = "DIR", description = "world files to sweep (a file belongs to the experiment its name starts with)")
    private Path worlds;

    @Option(names = "--generate", paramLabel = "K", description = "K generated worlds per experiment, generator seeds 1..K (default 10 without --worlds)")
    private Integer generate;

    @Option(names = "--world-seeds", paramLabel = "SEEDS",
            description = "generated worlds of these generator seeds (1..N, N or a list), e.g. 51..100 for worlds kept out of tuning")
    private String worldSeeds;

    @Option(names = "--max-side", paramLabel = "M", description = "with generated worlds: largest arena side in metres (default 3, wide profile 4)")
    private Double maxSide;

    @Option(names = "--profile", paramLabel = "P", description = "with generated worlds: classic (1-3 m, open, the range first measured) "
            + "or wide (0.7-4 m, a doorway or corridor, areas anywhere, sliding boxes) (default ${DEFAULT-VALUE})")
    private String profile = "classic";

    @Option(names = "--seeds", paramLabel = "SEEDS", description = "run seeds: 1..N, N or a list (default ${DEFAULT-VALUE})")
    private String seeds = "1..2";

    @Option(names = "--controllers", split = ",", paramLabel = "C", description = "agent, baseline (the thesis' C programs) and/or equal (the equal-capability baseline: "
            + "the same programs with the agents' strategies) (default agent,baseline)")
    private List<String> controllers = List.of(SweepJob.AGENT, SweepJob.BASELINE);

    @Option(names = "--agent", paramLabel = "FILE", description = "the agent to run (only with one EXPERIMENT), e.g. the thesis' as published: agents/src/main/asl/as-published/navigation.asl, found from any folder (default: the packaged one)")
    private Path agent;

    @Option(names = "--agents", paramLabel = "NAMES", split = ",", description = "the robot programmed by several agents "
            + "(only with one EXPERIMENT), as jacabot experiment --agents: suspend-resume: task,energy")
    private List<String> agentNames;

    @Option(names = "--jobs", paramLabel = "J", description = "runs at once (default: one per core, here ${DEFAULT-VALUE})")
    private int jobs = Runtime.getRuntime().availableProcessors();

    @Option(names = "--duration", paramLabel = "T", description = "simulated time per run (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--timeout", paramLabel = "T", description = "wall-clock bound per run; past it the run is a hang (default ${DEFAULT-VALUE})")
    private String timeout = "30m";

    @Option(names = "--shard", paramLabel = "I/N", description = "run only the I-th of N slices of the runs (I in 1..N)")
    private String shard;

    @Option(names = "--out", paramLabel = "DIR", description = "where the files go (default runs/sweep, or runs/sweep-I-of-N with --shard)")
    private Path out;

    @Option(names = "--no-progress", description = "no progress bar on stderr")
    private boolean noProgress;

    @Option(names = "--socket", description = "agent runs talk over a loopback socket, as `jacabot experiment` does "
            + "(default: the same frames in memory; the logs are the same, the socket is slower)")
    private boolean socket;

    @Option(names = "--pipeline", description = "agent runs in a pipelined lockstep: the world simulates the next control "
            + "step while the agent reasons, and its commands take effect one control step later (a different run; "
            + "docs/performance.md section 17)")
    private boolean pipeline;

    @CommandLine.Mixin
    private VerbosityOptions verbosity = new VerbosityOptions();

    @Override
    public Integer call() throws IOException, InterruptedException {
        PrintWriter o = spec.commandLine().getOut();
        var log = verbosity.console(spec);
        List<Experiment> experiments;
        double seconds, wallLimit;
        List<Long> runSeeds;
        List<Long> generatorSeeds = null;
        Profile worldProfile;
        int shardIndex = 1, shards = 1;
        try {
            if (experiment == null) {
                throw new IllegalArgumentException("which experiment? (obstacle-avoidance, object-picking, navigation, suspend-resume, tidy-up, all or team-delivery)");
            }
            if (experiment.equals("all")) {
                experiments = Experiment.thesis();
            } else {
                experiments = List.of(Experiment.parse(experiment).orElseThrow(() -> new IllegalArgumentException(
                        "unknown experiment '" + experiment + "' (expected obstacle-avoidance, object-picking, navigation, suspend-resume, tidy-up, all or team-delivery)")));
            }
            seconds = ExperimentCommand.parseDuration(duration);
            wallLimit = ExperimentCommand.parseDuration(timeout);
            if (!(seconds > 0) || !(wallLimit > 0)) {
                throw new IllegalArgumentException("--duration and --timeout must be positive");
            }
            runSeeds = SweepPlan.seeds(seeds);
            if (jobs < 1) {
                throw new IllegalArgumentException("--jobs must be at least 1, got " + jobs);
            }
            for (String c : controllers) {
                if (!SweepJob.CONTROLLERS.contains(c)) {
                    throw new IllegalArgumentException("unknown controller '" + c + "' (expected agent, baseline, equal)");
                }
            }
            if (shard != null) {
                var m = Pattern.compile("(\\d+)/(\\d+)").matcher(shard.trim());
                if (!m.matches() || Integer.parseInt(m.group(2)) < 1 || Integer.parseInt(m.group(1)) < 1
                        || Integer.parseInt(m.group(1)) > Integer.parseInt(m.group(2))) {
                    throw new IllegalArgumentException("bad --shard '" + shard + "' (expected I/N with 1 <= I <= N, e.g. 2/8)");
                }
                shardIndex = Integer.parseInt(m.group(1));
                shards = Integer.parseInt(m.group(2));
            }
            if (agent != null && experiment.equals("all")) {
                throw new IllegalArgumentException("--agent needs one EXPERIMENT, not all");
            }
            if (agentNames != null && experiment.equals("all")) {
                throw new IllegalArgumentException("--agents needs one EXPERIMENT, not all");
            }
            if (worlds != null && generate != null) {
                throw new IllegalArgumentException("--worlds and --generate exclude each other");
            }
            if (worldSeeds != null && (worlds != null || generate != null)) {
                throw new IllegalArgumentException("--world-seeds excludes --worlds and --generate");
            }
            if (worldSeeds != null) {
                generatorSeeds = SweepPlan.seeds(worldSeeds);
            }
            if (worlds != null) {
                worlds = Installation.locate(worlds); // --worlds worlds: the bundled ones, from anywhere
            }
            if (worlds != null && !Files.isDirectory(worlds)) {
                throw new IllegalArgumentException(worlds + ": no such directory");
            }
            if (generate != null && generate < 1) {
                throw new IllegalArgumentException("--generate must be at least 1, got " + generate);
            }
            if (maxSide != null && !(maxSide >= 1)) {
                throw new IllegalArgumentException("--max-side must be at least 1 (metres), got " + maxSide);
            }
            worldProfile = Profile.parse(profile);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        AgentSource agentSource = null;
        if (agent != null) {
            try {
                Path file = Installation.locate(agent);
                agentSource = ExperimentCommand.readAgent(file);
                agentSource.parse(agentSource.parser()); // a syntax error before, not in every run
                agent = file;
            } catch (AslSyntaxException e) {
                throw UserError.located(e.getMessage()); // file:line:col: error: ...
            }
        }
        Path dir = out != null ? out : Path.of("runs", shards == 1 ? "sweep" : "sweep-" + shardIndex + "-of-" + shards);
        OutPlace.directory("--out", dir);
        Files.createDirectories(dir.resolve("logs"));
        List<SweepPlan.World> list = worlds != null ? SweepPlan.directory(experiments, worlds)
                : SweepPlan.generated(experiments, generatorSeeds != null ? generatorSeeds
                        : SweepPlan.firstSeeds(generate == null ? 10 : generate), worldProfile, maxSide, dir.resolve("worlds"));
        if (list.isEmpty()) {
            throw new UserError(worlds + ": no world files for " + experiment + " (*.json whose name starts with the experiment)");
        }
        List<SweepJob> jobList = SweepPlan.jobs(list, runSeeds, controllers, shardIndex, shards);
        log.info(String.format(Locale.ROOT, "Sweep: %s (%s x %s x %s%s), %s simulated each, %d at once; %s",
                count(jobList.size(), "run"), count(list.size(), "world"), count(runSeeds.size(), "seed"),
                count(controllers.size(), "controller"),
                shards == 1 ? "" : ", shard " + shardIndex + " of " + shards, duration, jobs, dir)
                + (pipeline ? "; agent runs pipelined (their commands one control step later)" : ""));
        SuccessCriteria.caveat(seconds).ifPresent(c -> log.warn(c + "; report.md says so too"));
        Sweep sweep = new Sweep(jobs, seconds, wallLimit).progress(noProgress ? null : log)
                .onResult(r -> writeLogs(dir.resolve("logs"), r, log)).socket(socket).pipeline(pipeline);
        if (agentSource != null) {
            sweep.agent(experiments.get(0), agentSource);
        }
        if (agentNames != null) {
            sweep.agents(experiments.get(0), RobotAgents.packaged(experiments.get(0), agentNames, agent != null ? "--agent" : null));
        }
        Sweep.Outcomes result = sweep.run(jobList);
        List<RunOutcome> runs = new ArrayList<>(result.runs());
        runs.sort(Sweep.ORDER);
        String throughput = String.format(Locale.ROOT, "%.2f simulated minutes per wall-clock second (%d runs, %d at once, %.0f s)",
                result.simulatedMinutesPerSecond(), runs.size(), jobs, result.wallSeconds())
                + (Double.isNaN(result.cpuSeconds()) ? "" : String.format(Locale.ROOT,
                        "; %.2f per CPU-second (%.0f s of CPU on %d cores)", result.simulatedMinutesPerCpuSecond(),
                        result.cpuSeconds(), Runtime.getRuntime().availableProcessors()))
                + (Double.isNaN(result.loadAtStart()) ? "" : String.format(Locale.ROOT, "; load average %.1f at the start",
                        result.loadAtStart()))
                + "." + (pipeline ? " Agent runs in a pipelined lockstep (--pipeline)." : "");
        Files.writeString(dir.resolve("runs.csv"), SweepReport.csv(runs), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("report.md"), SweepReport.markdown(runs, throughput), StandardCharsets.UTF_8);
        Properties meta = new Properties();
        meta.setProperty("wall_s", String.format(Locale.ROOT, "%.3f", result.wallSeconds()));
        meta.setProperty("jobs", Integer.toString(jobs));
        if (!Double.isNaN(result.cpuSeconds())) {
            meta.setProperty("cpu_s", String.format(Locale.ROOT, "%.3f", result.cpuSeconds()));
        }
        meta.setProperty("shard", shardIndex + "/" + shards);
        try (var w = Files.newBufferedWriter(dir.resolve("sweep.properties"), StandardCharsets.UTF_8)) {
            meta.store(w, "jacabot sweep");
        }
        SweepReport.markdown(runs, throughput).lines().forEach(log::result);
        log.result("");
        log.result("Written: " + dir.resolve("runs.csv") + ", report.md, logs/");
        return 0;
    }

    /** A run's event log, and why it failed; a success removes the failure a sweep before it into the same directory left. */
    static void writeLogs(Path logs, SweepRun.Result r, ConsoleLog log) {
        RunOutcome o = r.outcome();
        String base = o.experiment().id() + "_" + o.world() + "_" + o.controller() + "_seed" + o.seed();
        try {
            Files.writeString(logs.resolve(base + ".events.txt"), r.eventLog(), StandardCharsets.UTF_8);
            Path failure = logs.resolve(base + ".failure.txt");
            if (!o.success()) {
                Files.writeString(failure, o.reason() + "\n\nlast console lines:\n"
                        + String.join("\n", r.consoleTail()) + "\n", StandardCharsets.UTF_8);
            } else {
                Files.deleteIfExists(failure);
            }
        } catch (IOException e) {
            log.warn("cannot write the logs of " + base + ": " + e.getMessage());
        }
    }

    /** {@return "1 run", "2 runs"} */
    static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    /** {@code jacabot sweep merge DIR...}: joins the CSVs of shards into one CSV and one report. */
    @Command(name = "merge", mixinStandardHelpOptions = true,
            description = "Joins the runs.csv of several sweep directories (e.g. shards) into OUT/runs.csv and OUT/report.md.")
    static final class Merge implements Callable<Integer> {
        @CommandLine.Spec
        private CommandLine.Model.CommandSpec spec;

        @Parameters(arity = "1..*", paramLabel = "DIR", description = "sweep directories, each holding runs.csv")
        private List<Path> dirs;

        @Option(names = "--out", paramLabel = "DIR", description = "where the joined files go (default ${DEFAULT-VALUE})")
        private Path out = Path.of("runs", "sweep-merged");

        @Override
        public Integer call() throws IOException {
            List<List<RunOutcome>> parts = new ArrayList<>();
            double rate = 0;
            boolean allRates = true;
            for (Path d : dirs) {
                Path csv = d.resolve("runs.csv");
                if (!Files.isRegularFile(csv)) {
                    throw new UserError(csv + ": no such file");
                }
                List<RunOutcome> runs;
                try {
                    runs = SweepReport.readCsv(csv);
                } catch (IllegalArgumentException e) {
                    throw new UserError(e.getMessage());
                }
                parts.add(runs);
                Path metaFile = d.resolve("sweep.properties");
                double wall = Double.NaN;
                if (Files.isRegularFile(metaFile)) {
                    Properties meta = new Properties();
                    try (var r = Files.newBufferedReader(metaFile, StandardCharsets.UTF_8)) {
                        meta.load(r);
                    }
                    try {
                        wall = Double.parseDouble(meta.getProperty("wall_s", "NaN"));
                    } catch (NumberFormatException e) {
                        wall = Double.NaN;
                    }
                }
                if (wall > 0) {
                    rate += runs.stream().mapToDouble(RunOutcome::simulated).sum() / 60 / wall;
                } else {
                    allRates = false;
                }
            }
            List<RunOutcome> all = SweepReport.merge(parts);
            String throughput = allRates ? String.format(Locale.ROOT,
                    "%.2f simulated minutes per wall-clock second (the sum of the %d parts' rates).", rate, dirs.size()) : null;
            OutPlace.directory("--out", out);
            Files.writeString(out.resolve("runs.csv"), SweepReport.csv(all), StandardCharsets.UTF_8);
            Files.writeString(out.resolve("report.md"), SweepReport.markdown(all, throughput), StandardCharsets.UTF_8);
            PrintWriter o = spec.commandLine().getOut();
            o.print(SweepReport.markdown(all, throughput));
            o.println();
            o.println("Written: " + out.resolve("runs.csv") + ", report.md");
            o.flush();
            return 0;
        }
    }
}
