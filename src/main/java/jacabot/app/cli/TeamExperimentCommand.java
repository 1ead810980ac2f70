package jacabot.app.cli;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.app.Installation;
import jacabot.app.console.ConsoleLog;
import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.ConsoleRecorder;
import jacabot.app.inspector.Inspector;
import jacabot.app.plot.RunPlots;
import jacabot.app.replay.StepLog;
import jacabot.app.replay.TeamTap;
import jacabot.app.run.AgentSource;
import jacabot.app.run.TeamLockstepRun;
import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.app.world.TeamWorld;
import jacabot.app.world.WorldGenerator;
import jacabot.cartago.CartagoException;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jacabot experiment team-delivery}: a team of Kheperas and their agents in one world, in
 * lockstep in one process (thesis Chapter 6), or {@code --baseline} the procedural team without
 * coordination. The launcher picks this command instead of {@link ExperimentCommand} when the
 * experiment named is team-delivery ({@link JacabotCommand#commandLine(String...)}).
 */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = {"Runs team-delivery: N Kheperas collect the arena's red cylinders into the storage area and "
                + "share one charger, one agent per robot coordinating through a task board and a charger queue, "
                + "in lockstep in one process, headless.",
                "The console's lines are prefixed by the robot ([khepera2] ...); the run ends with a summary per robot and one for the team."})
final class TeamExperimentCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", description = "team-delivery")
    private String name;

    @Option(names = "--robots", paramLabel = "N", description = "the team's size: the world's first N robots "
            + "(default: every robot of the world; the packaged world has 4)")
    private Integer robots;

    @Option(names = "--seed", paramLabel = "N", description = "seed of the world and the agents (default: the world file's)")
    private Long seed;

    @Option(names = "--duration", paramLabel = "T", description = "simulated time: 90s, 10m, ... (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--world", paramLabel = "FILE", description = "the world file (default worlds/team-delivery.json)")
    private Path world;

    @Option(names = "--agent", paramLabel = "FILE", description = "every robot's agent (default: the packaged "
            + "agents/src/main/asl/team-delivery.asl)")
    private Path agent;

    @Option(names = "--baseline", description = "run N copies of experiment 4's procedural baseline, without coordination")
    private boolean baseline;

    @Option(names = "--out", paramLabel = "DIR", description = "where the summaries and event logs go "
            + "(default runs/team-delivery[-WORLD][-baseline]-NROBOTS-SEED)")
    private Path out;

    @Option(names = "--link-log", description = "also write OUT/ROBOT/link-log.txt: the robot's controller's event log, "
            + "a line per control step's readings, applied command and pose")
    private boolean linkLog;

    @Option(names = "--remote-controller", description = "the agents' side only: robot i's link waits on --port + i "
            + "(default 4444 + i) for `jacabot controller --lockstep` with the same world file, team and seed in another process, "
            + "and runs with it step by step (the same run as in one process)")
    private boolean remoteController;

    @Option(names = "--port", paramLabel = "PORT", description = "with --remote-controller: the first robot's port (default 4444)")
    private int port = Protocol.DEFAULT_PORT;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "with --remote-controller: the link secret shared with the controller (default ~/.jacabot/link-secret)")
    private Path secretFile;

    @Option(names = "--headless", description = "accepted for symmetry with the other experiments: a team always runs headless")
    private boolean headless;

    @Mixin
    private VerbosityOptions verbosity = new VerbosityOptions();

    @Mixin
    private InspectorOptions inspectorOptions = new InspectorOptions();

    @Spec
    private CommandSpec commandSpec;

    @Override
    public Integer call() throws Exception {
        if (!WorldGenerator.TEAM_DELIVERY.equals(name)) {
            throw new UserError("unknown team experiment '" + name + "' (expected team-delivery)");
        }
        ConsoleLog log = verbosity.console(commandSpec);
        double seconds = ExperimentCommand.duration(duration);
        ExperimentCommand.agentOrBaseline(baseline, agent);
        Path worldFile = world != null ? Installation.locate(world) : Installation.resolve("worlds/team-delivery.json");
        WorldSpec spec = teamWorld(worldFile, robots);
        long runSeed = seed != null ? seed : spec.seed();
        int n = spec.robots().size();
        AgentSource source = agent != null ? ExperimentCommand.readAgent(Installation.locate(agent))
                : AgentSource.resource("/asl/team-delivery.asl", "agents/src/main/asl/team-delivery.asl");
        if (remoteController) {
            return runWithRemoteController(spec, source, runSeed, seconds, log);
        }
        Path outDir = out != null ? out : runFolder(world == null ? null : worldFile, baseline, n, runSeed);
        OutPlace.directory("--out", outDir);
        log.info("Team delivery: " + n + (n == 1 ? " Khepera" : " Kheperas") + ", world " + Installation.shown(worldFile) + ", seed " + runSeed + ", " + duration
                + " of simulated time, " + (baseline ? "procedural baseline (no coordination)" : "agent " + source.name())
                + ", lockstep.");
        long t0 = System.nanoTime();
        TeamDeliveryRun.Outcome outcome;
        Inspector inspector = null;
        if (baseline) {
            outcome = TeamDeliveryRun.baseline(spec, runSeed, seconds);
        } else {
            // every agent's lines, each with its robot's name, by simulated time: the team's console.txt
            var world = new AtomicReference<SimWorld>();
            ConsoleRecorder consoleFile = ConsoleRecorder.open(outDir, () -> world.get() == null ? 0 : world.get().timeMs());
            PrintStream console = consoleFile.tee(log.agents());
            long every = 60_000;
            inspector = inspectorOptions.start(false, "team-delivery, " + n + " robots, seed " + runSeed,
                    ConsoleLog.lines(log::result), log::warn);
            Inspector page = inspector;
            if (inspector != null) {
                inspector.console(ConsoleFile.of(outDir));
            }
            try (consoleFile) { // every robot's step log (DIR/ROBOT/steps.jsonl.gz) and mind in the inspector
                outcome = TeamDeliveryRun.agents(spec, source, runSeed, seconds, console, linkLog, t -> {
                    consoleFile.events(List.of()); // on disk at each control step
                    if (t > 0 && t % every == 0) {
                        log.info(String.format(Locale.ROOT, "t=%d s", t / 1000));
                    }
                }, run -> {
                    world.set(run.world());
                    return TeamTap.attach(run, page, outDir, WorldGenerator.TEAM_DELIVERY, source.name());
                });
            } catch (AslSyntaxException e) {
                throw UserError.located(e.getMessage());
            } catch (CartagoException e) {
                throw new IllegalStateException("cannot make the team's artifacts: " + e.getMessage(), e);
            }
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        List<String> text = summary(outcome, worldFile, baseline ? null : source.name(), wall);
        write(outDir, outcome, text);
        log.info("");
        text.forEach(log::result);
        log.result("Written: " + outDir.resolve("summary.txt") + (baseline ? "" : ", console.txt") + ", and per robot ROBOT/summary.json, ROBOT/event-log.txt"
                + (linkLog && !baseline ? ", ROBOT/link-log.txt" : "")
                + (baseline ? "" : ", ROBOT/" + StepLog.FILE + " (jacabot replay " + outDir + " --headless --inspector)"));
        if (!baseline) {
            RunPlots.writeTeam(outDir, ConsoleLog.lines(log::result));
        }
        if (inspector != null) {
            inspector.showPlots(outDir);
            inspectorOptions.linger(inspector, ConsoleLog.lines(log::result));
            inspector.close();
        }
        if (outcome.agentFailure().isPresent()) {
            throw new RunFailure(outcome.agentFailure().get());
        }
        if (!outcome.departures().isEmpty()) {
            throw new RunFailure("an agent left the team: " + outcome.departures().get(0));
        }
        return 0;
    }

    /**
     * The agents' side of a team in two processes: the world, its summaries and its logs are the
     * controllers' ({@code jacabot controller --lockstep --world FILE [--robots N] [--seed S] --out DIR}).
     */
    private int runWithRemoteController(WorldSpec spec, AgentSource source, long runSeed, double seconds, ConsoleLog log)
            throws Exception {
        int n = spec.robots().size();
        if (baseline || linkLog || out != null) {
            throw new UserError((baseline ? "--baseline" : linkLog ? "--link-log" : "--out")
                    + " goes with the controllers' process when they are remote: `jacabot controller --lockstep ... --out DIR --link-log`");
        }
        if (port < 1 || port + n - 1 > 65535) {
            throw new UserError("--port must leave " + n + " ports in 1..65535 (robot i listens on --port + i), got " + port);
        }
        try {
            LinkSecret.useInThisProcess(secretFile != null ? LinkSecret.loadOrCreate(secretFile) : LinkSecret.userDefault());
        } catch (IOException | UncheckedIOException e) {
            throw new UserError(e.getMessage() + (secretFile == null ? " (or pass --secret-file FILE)" : ""));
        }
        TeamLockstepRun made;
        try {
            made = new TeamLockstepRun(SimWorld.of(TeamDeliveryRun.withSeed(spec, runSeed)), source, runSeed, log.agents());
        } catch (AslSyntaxException e) {
            throw UserError.located(e.getMessage());
        } catch (CartagoException e) {
            throw new IllegalStateException("cannot make the team's artifacts: " + e.getMessage(), e);
        }
        try (TeamLockstepRun run = made) {
            run.remoteController(true).port(port);
            log.info("Waiting for `jacabot controller --lockstep --world FILE" + (robots != null ? " --robots " + robots : "")
                    + " --seed " + runSeed + " --port " + port + "` with the same world file (robot i on port " + port + " + i).");
            long[] steps = {0};
            run.onStep(t -> steps[0]++);
            try {
                run.runFor(seconds);
            } catch (IOException e) {
                throw new IllegalStateException("cannot listen on ports " + port + ".." + (port + n - 1) + " (" + e.getMessage()
                        + "); choose others with --port", e);
            }
            log.result(String.format(Locale.ROOT, "%d steps (%.1f s simulated) with the remote controllers, %d robots, %d reasoning cycles.",
                    steps[0], steps[0] * spec.controlStep() / 1000.0, n, run.cycles()));
            run.departures().forEach(d -> log.result("agent left: " + d));
            if (run.agentFailure().isPresent()) {
                throw new RunFailure(run.agentFailure().get());
            }
            if (!run.departures().isEmpty()) {
                throw new RunFailure("an agent left the team: " + run.departures().get(0));
            }
        }
        return 0;
    }

    /** {@return the world's spec with its first {@code robots} robots} @throws UserError when it cannot serve a team */
    static WorldSpec teamWorld(Path worldFile, Integer robots) {
        WorldSpec spec;
        try {
            spec = WorldFileReader.read(worldFile);
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
        int n = robots != null ? robots : spec.robots().size();
        if (n < 1) {
            throw new UserError("--robots must be at least 1, got " + n);
        }
        var missing = TeamWorld.missing(spec, n, Installation.shown(worldFile));
        if (missing.isPresent()) {
            throw new UserError(missing.get()); // a world file's error, said as the reader's are: error: file: $.path: problem
        }
        try {
            return TeamWorld.firstRobots(spec, n);
        } catch (IllegalArgumentException e) {
            throw new UserError(Installation.shown(worldFile) + ": " + e.getMessage());
        }
    }

    static Path runFolder(Path world, boolean baseline, int robots, long seed) {
        var name = new StringBuilder(WorldGenerator.TEAM_DELIVERY);
        if (world != null && !world.getFileName().toString().equals(WorldGenerator.TEAM_DELIVERY + ".json")) {
            String n = world.getFileName().toString();
            name.append('-').append(n.endsWith(".json") ? n.substring(0, n.length() - 5) : n);
        }
        if (baseline) {
            name.append("-baseline");
        }
        return Path.of("runs", name.append('-').append(robots).append("robots-").append(seed).toString());
    }

    /** {@return the summary's lines: one per robot, then the team's and the verdict} */
    static List<String> summary(TeamDeliveryRun.Outcome o, Path worldFile, String agentName, double wallSeconds) {
        List<String> lines = new ArrayList<>();
        lines.add("team-delivery, " + o.robots().size() + " robots, seed " + o.seed() + ", world " + Installation.shown(worldFile) + ", "
                + (agentName == null ? "procedural baseline" : "agent " + agentName));
        var f = o.figures();
        for (int i = 0; i < o.robots().size(); i++) {
            RunSummary r = o.robots().get(i);
            lines.add(String.format(Locale.ROOT, "[%s] picks %d, deliveries %d, contact %.1f s (with robots %.1f s), battery min %s J%s, "
                            + "charger visits %d, distance %.1f m", r.robot(), r.picks(), r.deliveries(), r.contactTime(),
                    f.robotContactTimes().get(i), r.batteryMin() == null ? "-" : String.format(Locale.ROOT, "%.0f", r.batteryMin()),
                    r.batteryEmptied() ? " (emptied)" : "", r.chargerVisits(), r.distance()));
        }
        lines.add(String.format(Locale.ROOT, "team: %d deliveries of %d cylinders in %.0f s; %s", f.deliveries(), f.cylinders(),
                f.duration(), o.baseline() ? "no coordination (no claims, no charger queue)"
                        : String.format(Locale.ROOT, "%d claims, %d double claims, %d charger waits (longest %.1f s)",
                        o.claims(), f.doubleClaims(), o.chargerWaits(), f.longestChargerWait())));
        lines.add("criteria: " + (o.verdict().success() ? "met" : "not met: " + o.verdict().reason()));
        lines.add(String.format(Locale.ROOT, "%.0f s simulated in %.1f s%s", f.duration(), wallSeconds,
                o.baseline() ? "" : ", " + o.cycles() + " reasoning cycles"));
        o.agentFailure().ifPresent(why -> lines.add("agent failure: " + why));
        o.departures().forEach(d -> lines.add("agent left: " + d));
        return lines;
    }

    private static void write(Path outDir, TeamDeliveryRun.Outcome o, List<String> text) throws IOException {
        Files.writeString(outDir.resolve("summary.txt"), String.join("\n", text) + "\n");
        for (RunSummary r : o.robots()) {
            Path dir = Files.createDirectories(outDir.resolve(r.robot()));
            r.writeJson(dir.resolve("summary.json"));
            Files.writeString(dir.resolve("event-log.txt"), r.eventLog());
            List<String> links = o.linkLogs().get(r.robot());
            if (links != null) {
                Files.write(dir.resolve("link-log.txt"), links);
            }
        }
    }
}
