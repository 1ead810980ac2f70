package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.bench.InterpreterBenchmark;
import jacabot.app.bench.LatencyBenchmark;
import jacabot.app.bench.SimulationBenchmark;
import jacabot.app.bench.TeamSimulationBenchmark;
import jacabot.app.run.AgentSource;
import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code jacabot bench ...}: benchmarks that print figures. */
@Command(name = "bench", mixinStandardHelpOptions = true, description = "Benchmarks that print figures.",
        subcommands = {BenchCommand.Interpreter.class, BenchCommand.Latency.class, BenchCommand.Simulation.class, BenchWorldCommand.class})
final class BenchCommand implements Runnable {
    @Spec
    private CommandSpec spec;

    @Override
    public void run() {
        var out = spec.commandLine().getOut();
        out.println("Usage: jacabot bench interpreter [--runs N] [--jason-classpath FILE] [--programs LIST] [--project FILE.mas2j] [--limit S]");
        out.println("       jacabot bench latency [--duration 60s] [--speed X]");
        out.println("       jacabot bench sim [--duration 10m] [--seed N] [--robots N]");
        out.flush();
    }

    /** Our interpreter against Jason 3.2.0, side by side. */
    @Command(name = "interpreter", mixinStandardHelpOptions = true,
            description = {"Runs the same AgentSpeak programs on our interpreter and on Jason 3.2.0, alternating, "
                    + "after a warm-up run each, and prints a Markdown table.",
                    "Jason is not a dependency of jacabot: `gradle benchInterpreter` fetches it and writes its class path "
                    + "to build/jason-classpath.txt."})
    static final class Interpreter implements Callable<Integer> {
        @Spec
        private CommandSpec spec;

        @Option(names = "--runs", description = "measured runs per program and interpreter (default ${DEFAULT-VALUE})")
        private int runs = 3;

        @Option(names = "--jason-classpath", paramLabel = "FILE",
                description = "a file holding Jason's class path (default ${DEFAULT-VALUE})")
        private Path jasonClasspath = Path.of("build/jason-classpath.txt");

        @Option(names = "--programs", split = ",", paramLabel = "LIST",
                description = "the programs to run, by name; `deep` stands for every deep recursion program (default: all)")
        private List<String> programs;

        @Option(names = "--limit", paramLabel = "S", description = "seconds a run may take before it is cut (default ${DEFAULT-VALUE})")
        private double limit = 300;

        @Option(names = "--project", paramLabel = "FILE",
                description = "a project of your own (.mas2j) to measure too, run in its directory; one of its agents prints "
                        + "`start` and `end` (.print(start), .print(end)) around what is measured. Repeatable; given alone, "
                        + "only these projects run. One that cannot be measured gets a row of dashes, the others still "
                        + "run, and the command ends with its error (exit 1)")
        private List<Path> projects = new ArrayList<>();

        @Option(names = "--ours-classpath", paramLabel = "FILE",
                description = "a file holding the class path of another build of ours to measure (default: this one)")
        private Path oursClasspath;

        @Override
        public Integer call() throws Exception {
            if (!Files.isRegularFile(jasonClasspath)) {
                throw new UserError(jasonClasspath + ": not found; run `gradle jasonClasspath` (or `gradle benchInterpreter`) first");
            }
            if (oursClasspath != null && !Files.isRegularFile(oursClasspath)) {
                throw new UserError("--ours-classpath: " + oursClasspath + ": not found");
            }
            if (programs != null) {
                var known = new ArrayList<>(InterpreterBenchmark.names());
                known.add("deep");
                for (String p : programs) {
                    if (!known.contains(p)) {
                        throw new UserError("--programs: unknown program '" + p + "' (one of " + String.join(", ", known) + ")");
                    }
                }
            }
            for (Path p : projects) {
                if (!Files.isRegularFile(p) || !p.getFileName().toString().endsWith(".mas2j")) {
                    throw new UserError("--project: " + p + ": not a .mas2j file");
                }
            }
            if (!(limit > 0)) {
                throw new UserError("--limit must be a positive number of seconds, got " + limit);
            }
            String jason = Files.readString(jasonClasspath).trim();
            String ours = oursClasspath == null ? System.getProperty("java.class.path") : Files.readString(oursClasspath).trim();
            new InterpreterBenchmark(ours, jason, Math.max(1, runs), ConsoleStreams.of(spec.commandLine().getOut()),
                    programs == null ? (projects.isEmpty() ? null : Set.of()) : Set.copyOf(programs), limit,
                    projects).run();
            return 0;
        }
    }

    /** Experiment 4 headless with the agent in the loop: real-time factor and where the time goes. */
    @Command(name = "sim", mixinStandardHelpOptions = true,
            description = "Runs experiment 4 headless in lockstep (agent, artifact, socket, controller, physics, sensors) "
                    + "and prints the real-time factor and the share of time in each part; then the procedural baseline.")
    static final class Simulation implements Callable<Integer> {
        @Spec
        private CommandSpec spec;

        @Option(names = "--duration", paramLabel = "T", description = "simulated time (default ${DEFAULT-VALUE})")
        private String duration = "10m";

        @Option(names = "--seed", description = "seed (default: the world file's, 13, as `jacabot experiment suspend-resume`)")
        private Long seed;

        @Option(names = "--root", paramLabel = "DIR", description = "a repository to take worlds/ from (default: the installation's)")
        private Path root;

        @Option(names = "--warmup", paramLabel = "N", description = "whole unmeasured runs first, while the JIT compiles (default ${DEFAULT-VALUE})")
        private int warmups = 4;

        @Option(names = "--warmup-max", paramLabel = "N", description = "more warm-up runs, up to N in all, until the JIT "
                + "compilers have taken at most 10%% of two runs' CPU in a row (default: 30 when --warmup is not given, "
                + "else --warmup; --warmup-max 4: the four runs measured before; docs/performance.md section 25)")
        private Integer warmupMax;

        @Option(names = "--runs", paramLabel = "N", description = "measured runs; the median one is reported (default ${DEFAULT-VALUE})")
        private int runs = 3;

        @Option(names = "--turns", description = "the simulation thread also reads and answers the middleware's end of "
                + "the socket, so no thread wakes up in a step (off by default: slower on a loaded machine; "
                + "docs/performance.md section 9)")
        private boolean turns;

        @Option(names = "--pipeline", description = "also the pipelined lockstep (the world simulates the next step while "
                + "the agent reasons; its answer applied one control step later), runs alternated with the lockstep's and "
                + "printed beside them (docs/performance.md section 17)")
        private boolean pipeline;

        @Option(names = "--robots", paramLabel = "N", description = "instead: team-delivery with a team of N robots against "
                + "one robot, runs alternated (worlds/team-delivery.json, its seed; default --duration 60s, --warmup 1)")
        private Integer robots;

        @Override
        public Integer call() throws Exception {
            if (warmups < 0 || runs < 1) {
                throw new UserError("--warmup must be 0 or more and --runs 1 or more, got " + warmups + " and " + runs);
            }
            if (robots != null) {
                return team();
            }
            Path world = CompareCommand.bundled(root, Experiment.SUSPEND_RESUME.worldFile());
            long runSeed;
            try {
                runSeed = seed != null ? seed : WorldFileReader.read(world).seed();
            } catch (WorldFileException e) {
                throw new UserError(e.getMessage());
            }
            new SimulationBenchmark(world, ExperimentCommand.duration(duration), runSeed, warmups, runs, turns,
                    ConsoleStreams.of(spec.commandLine().getOut())).pipeline(pipeline)
                    .settleWithin(warmupMax != null ? warmupMax : warmupGiven() ? warmups : DEFAULT_WARMUP_MAX).run();
            return 0;
        }

        /** Warm-up runs at most when neither {@code --warmup} nor {@code --warmup-max} is given. */
        private static final int DEFAULT_WARMUP_MAX = 30;

        private boolean warmupGiven() {
            return spec.commandLine().getParseResult().matchedOption("--warmup") != null;
        }

        /** {@code --robots N}: the team's cost per simulated second against one robot's. */
        private int team() throws Exception {
            Path file = CompareCommand.bundled(root, "worlds/team-delivery.json");
            WorldSpec world;
            try {
                world = WorldFileReader.read(file);
            } catch (WorldFileException e) {
                throw new UserError(e.getMessage());
            }
            if (robots < 1 || robots > world.robots().size()) {
                throw new UserError("--robots must be in 1.." + world.robots().size() + " (the robots of " + Installation.shown(file)
                        + "), got " + robots);
            }
            boolean defaultDuration = spec.commandLine().getParseResult().matchedOption("--duration") == null;
            boolean defaultWarmup = spec.commandLine().getParseResult().matchedOption("--warmup") == null;
            AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "agents/src/main/asl/team-delivery.asl");
            new TeamSimulationBenchmark(world, agent, robots, ExperimentCommand.duration(defaultDuration ? "60s" : duration),
                    seed != null ? seed : world.seed(), defaultWarmup ? 1 : warmups, runs, ConsoleStreams.of(spec.commandLine().getOut())).run();
            return 0;
        }
    }

    /** Reactive and response time over the real socket, in real time and in lockstep. */
    @Command(name = "latency", mixinStandardHelpOptions = true,
            description = "Measures the thesis' reactive and response times over the real socket, in real time and in "
                    + "lockstep: a box moved in front of the robot and away every 120 simulated ms, the agent answering "
                    + "each obstacle change with stop.")
    static final class Latency implements Callable<Integer> {
        @Spec
        private CommandSpec spec;

        @Option(names = "--duration", paramLabel = "T", description = "simulated time in real-time mode (default ${DEFAULT-VALUE}); lockstep runs four times longer")
        private String duration = "120s";

        @Option(names = "--speed", paramLabel = "X", description = "real time x this factor (default ${DEFAULT-VALUE})")
        private double speed = 8;

        @Option(names = "--root", paramLabel = "DIR", description = "a repository to take worlds/ from (default: the installation's)")
        private Path root;

        @Override
        public Integer call() throws Exception {
            if (!(speed > 0) || Double.isInfinite(speed)) {
                throw new UserError("--speed must be a positive number, got " + speed);
            }
            new LatencyBenchmark(CompareCommand.bundled(root,
                    Experiment.OBSTACLE_AVOIDANCE.worldFile()), ExperimentCommand.duration(duration), speed,
                    ConsoleStreams.of(spec.commandLine().getOut())).run();
            return 0;
        }
    }
}
