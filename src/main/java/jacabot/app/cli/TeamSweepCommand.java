package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.console.ConsoleLog;
import jacabot.app.run.AgentSource;
import jacabot.app.sweep.SweepPlan;
import jacabot.app.sweep.SweepRun;
import jacabot.app.sweep.TeamDeliveryRun;
import jacabot.app.world.TeamWorld;
import jacabot.app.world.WorldGenerator;
import jacabot.robot.run.RunSummary;
import jacabot.sim.world.WorldSpec;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jacabot sweep team-delivery}: teams of 1, 2, 4 ... robots, coordinated (agents) and not
 * (the procedural baseline), on generated team worlds x seeds, or on a folder of team world files
 * ({@code --worlds}). Each arena serves every team size (a team of N keeps the first N robots, in
 * their places), so the sizes compare. Writes
 * OUT/runs.csv (a row per run) and OUT/report.md (deliveries per team size and controller, and
 * each size's ratio to one robot on the same worlds and seeds).
 */
@Command(name = "sweep", mixinStandardHelpOptions = true,
        description = {"Runs team-delivery over generated team worlds (or the team world files of --worlds) x seeds for each team size, agents and the "
                + "procedural baseline, and judges each run by the team criteria (docs/teams.md).",
                "Writes OUT/runs.csv and OUT/report.md. Exit 0 when every run was made (failed runs included), 2 on bad usage."})
final class TeamSweepCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "EXPERIMENT", description = "team-delivery")
    private String experiment;

    @Option(names = "--robots", split = ",", paramLabel = "N", description = "team sizes (default ${DEFAULT-VALUE})")
    private List<Integer> robots = List.of(1, 2, 4);

    @Option(names = "--world-seeds", paramLabel = "SEEDS", description = "generated team worlds of these generator seeds: "
            + "1..K or a list (default 1..5)")
    private String worldSeeds;

    @Option(names = "--worlds", paramLabel = "DIR", description = "team world files instead of generated worlds: the *.json in "
            + "DIR named team-delivery... or for no single-robot experiment, in name order; each must hold as many Kheperas "
            + "as the largest team, a storage point and a charger")
    private Path worldFiles;

    @Option(names = "--cylinders", paramLabel = "MIN..MAX", description = "the generated worlds' red cylinders, drawn in "
            + "MIN..MAX (default 10..14, the range the team's targets were set on; another range gives other worlds)")
    private String cylinders;

    @Option(names = "--seeds", paramLabel = "SEEDS", description = "run seeds: 1..N or a list (default ${DEFAULT-VALUE})")
    private String seeds = "1";

    @Option(names = "--controllers", split = ",", paramLabel = "C", description = "agents, baseline or both (default agents,baseline)")
    private List<String> controllers = List.of("agents", "baseline");

    @Option(names = "--duration", paramLabel = "T", description = "simulated time per run (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--jobs", paramLabel = "J", description = "runs at once (default ${DEFAULT-VALUE})")
    private int jobs = 1;

    @Option(names = "--out", paramLabel = "DIR", description = "where runs.csv and report.md go (default ${DEFAULT-VALUE})")
    private Path out = Path.of("runs", "sweep-team-delivery");

    @Option(names = "--no-progress", description = "no line per finished run (as the single-robot sweep's progress bar)")
    private boolean noProgress;

    @Option(names = "--logs", description = "per agents' run, OUT/logs/W-Nr-sS/: the agents' console, every robot's "
            + "event log and the world's cylinders (to see where the time and the cylinders went)")
    private boolean logs;

    @Mixin
    private VerbosityOptions verbosity = new VerbosityOptions();

    @Spec
    private CommandSpec commandSpec;

    /** One run of the sweep and what it gave: its outcome, or why it crashed (then {@code outcome} is null). */
    record Row(String world, int robots, String controller, long seed, TeamDeliveryRun.Outcome outcome, String crash) {
        boolean crashed() {
            return outcome == null;
        }
    }

    @Override
    public Integer call() throws Exception {
        if (!WorldGenerator.TEAM_DELIVERY.equals(experiment)) {
            throw new UserError("unknown team experiment '" + experiment + "' (expected team-delivery)");
        }
        ConsoleLog log = verbosity.console(commandSpec);
        double seconds = ExperimentCommand.duration(duration);
        List<Long> runSeeds = seedsOf("--seeds", seeds);
        WorldGenerator.CylinderRange range = cylinders == null ? WorldGenerator.CylinderRange.TEAM
                : WorldCommand.Generate.cylinderRange(cylinders);
        if (jobs < 1 || robots.stream().anyMatch(n -> n < 1 || n > WorldGenerator.MAX_TEAM)) {
            throw new UserError("--jobs must be at least 1, --robots 1.." + WorldGenerator.MAX_TEAM);
        }
        if (worldFiles != null && (worldSeeds != null || cylinders != null)) {
            throw new UserError("--worlds excludes --world-seeds and --cylinders (they make generated worlds)");
        }
        for (String c : controllers) {
            if (!c.equals("agents") && !c.equals("baseline")) {
                throw new UserError("--controllers: '" + c + "' (expected agents, baseline or both)");
            }
        }
        int largest = robots.stream().mapToInt(Integer::intValue).max().orElse(1);
        // every world is read and checked before the first run: a bad file is one line, not a sweep of crashes
        List<Arena> arenas = worldFiles != null ? worldFiles(Installation.locate(worldFiles), largest)
                : generated(seedsOf("--world-seeds", worldSeeds == null ? "1..5" : worldSeeds), largest, range);
        OutPlace.directory("--out", out);
        AgentSource agent = AgentSource.resource("/asl/team-delivery.asl", "agents/src/main/asl/team-delivery.asl");
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        ExecutorService pool = Executors.newFixedThreadPool(jobs);
        List<Future<Row>> futures = new ArrayList<>();
        // runs.csv is written again as each run ends, so a sweep stopped midway keeps the runs it made
        Map<Integer, Row> finished = new ConcurrentSkipListMap<>();
        Path csvFile = out.resolve("runs.csv");
        for (Arena arena : arenas) {
            WorldSpec spec = arena.spec();
            for (long seed : runSeeds) {
                for (int n : robots) {
                    WorldSpec team = TeamWorld.firstRobots(spec, n);
                    for (String c : controllers) {
                        String world = arena.name();
                        int index = futures.size();
                        futures.add(pool.submit(() -> {
                            Row row;
                            // one run's exception is that run's crash: the sweep goes on, as the single-robot sweep does
                            try {
                                Path dir = logs && c.equals("agents")
                                        ? out.resolve("logs").resolve(arena.logName() + "-" + n + "r-s" + seed) : null;
                                TeamDeliveryRun.Outcome o;
                                if (c.equals("baseline")) {
                                    o = TeamDeliveryRun.baseline(team, seed, seconds);
                                } else if (dir == null) {
                                    o = TeamDeliveryRun.agents(team, agent, seed, seconds, quiet, false, null);
                                } else {
                                    o = agentsWithLogs(team, agent, seed, seconds, dir);
                                }
                                row = new Row(world, n, c, seed, o, "");
                            } catch (RuntimeException e) {
                                row = new Row(world, n, c, seed, null, SweepRun.describe(e));
                            }
                            if (!noProgress) {
                                log.info(String.format(Locale.ROOT, "world %s seed %d, %d robot%s, %s: %s", arena.logName(), seed, n,
                                        n == 1 ? "" : "s", c, row.crashed() ? "crash (" + row.crash() + ")"
                                                : row.outcome().deliveries() + " deliveries"
                                                        + (success(row.outcome()) ? "" : " (" + reason(row.outcome()) + ")")));
                            }
                            finished.put(index, row);
                            writeCsv(csvFile, finished);
                            return row;
                        }));
                    }
                }
            }
        }
        pool.shutdown();
        List<Row> rows = new ArrayList<>();
        for (Future<Row> f : futures) {
            rows.add(f.get()); // runs.csv is whole already: each run wrote it after its row was in
        }
        String report = report(rows, seconds, range);
        Files.writeString(out.resolve("report.md"), report);
        report.lines().forEach(log::result);
        log.result("Written: " + out.resolve("runs.csv") + ", " + out.resolve("report.md"));
        return 0;
    }

    /** A world of the sweep: its name in runs.csv, the start of its runs' log folders, and the world itself. */
    private record Arena(String name, String logName, WorldSpec spec) {
    }

    /** {@return the generated team worlds of these generator seeds (team-delivery-gen-S; logs S-Nr-sR)} */
    private static List<Arena> generated(List<Long> seeds, int largest, WorldGenerator.CylinderRange range) {
        return seeds.stream().map(w -> new Arena(WorldGenerator.TEAM_DELIVERY + "-gen-" + w, Long.toString(w),
                WorldGenerator.team(largest, w).cylinders(range).generate().spec())).toList();
    }

    /** {@return DIR's team world files in name order, each named by its file name without .json} @throws UserError on a bad one */
    private static List<Arena> worldFiles(Path dir, int largest) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw new UserError("--worlds: " + dir + ": no such directory");
        }
        List<Path> files;
        try (var s = Files.list(dir)) {
            files = s.filter(p -> Files.isRegularFile(p) && teamFile(p.getFileName().toString())).sorted().toList();
        }
        if (files.isEmpty()) {
            throw new UserError("--worlds: " + dir + ": no team world files (*.json not named for a single-robot experiment)");
        }
        List<Arena> out = new ArrayList<>();
        for (Path f : files) {
            String name = f.getFileName().toString();
            name = name.substring(0, name.length() - ".json".length());
            out.add(new Arena(name, name, TeamExperimentCommand.teamWorld(f, largest)));
        }
        return out;
    }

    /** {@return whether a file is a team world: as the single-robot sweep's rule, named for the team or for no experiment} */
    private static boolean teamFile(String name) {
        return name.endsWith(".json") && (name.startsWith(WorldGenerator.TEAM_DELIVERY) || SweepPlan.namedForNoExperiment(name));
    }

    /** The agents' run, its console (each line after its simulated time), event logs and world written to {@code dir}. */
    private static TeamDeliveryRun.Outcome agentsWithLogs(WorldSpec team, AgentSource agent, long seed, double seconds, Path dir)
            throws Exception {
        Files.createDirectories(dir);
        var now = new AtomicLong(); // the simulated time of the last control step, ms
        TeamDeliveryRun.Outcome o;
        try (var file = Files.newBufferedWriter(dir.resolve("console.txt"));
                PrintStream console = ConsoleStreams.stamped(file, now::get)) {
            o = TeamDeliveryRun.agents(team, agent, seed, seconds, console, false, now::set);
        }
        writeLogs(dir, team, o);
        return o;
    }

    /** Writes every robot's event log (prefixed with its name) and the world's cylinders, storage and charger. */
    private static void writeLogs(Path dir, WorldSpec team, TeamDeliveryRun.Outcome o) throws IOException {
        var sb = new StringBuilder();
        for (RunSummary s : o.robots()) {
            s.events().forEach(e -> sb.append(s.robot()).append(' ').append(e).append('\n'));
        }
        Files.writeString(dir.resolve("events.txt"), sb);
        var w = new StringBuilder(String.format(Locale.ROOT, "arena %.3f %.3f%nstorage %.3f %.3f %.3f%ncharger %.3f %.3f%n",
                team.arena().width(), team.arena().depth(), team.storage().x(), team.storage().z(), team.storage().radius(),
                team.charger().x(), team.charger().z()));
        team.cylinders().forEach(c -> w.append(String.format(Locale.ROOT, "cylinder %s %.3f %.3f%n", c.id(), c.x(), c.z())));
        Files.writeString(dir.resolve("world.txt"), w);
    }

    private static List<Long> seedsOf(String option, String text) {
        try {
            return SweepPlan.seeds(text);
        } catch (IllegalArgumentException e) {
            throw new UserError(option + ": " + e.getMessage());
        }
    }

    /** {@return whether a run met the team's criteria; one whose agent failed at its job did not} */
    private static boolean success(TeamDeliveryRun.Outcome o) {
        return o.verdict().success() && o.agentFailure().isEmpty();
    }

    /** {@return why a run failed: its agent's failure first (e.g. reasoning that ran away), then the criteria not met} */
    private static String reason(TeamDeliveryRun.Outcome o) {
        String criteria = o.verdict().reason();
        return o.agentFailure().map(f -> "agent failure: " + f + (criteria.isEmpty() ? "" : "; " + criteria)).orElse(criteria);
    }

    private static synchronized void writeCsv(Path file, Map<Integer, Row> finished) throws IOException {
        Path part = file.resolveSibling(file.getFileName() + ".part");
        Files.writeString(part, csv(List.copyOf(finished.values())));
        Files.move(part, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    static String csv(List<Row> rows) {
        var sb = new StringBuilder("world,robots,controller,seed,deliveries,per_robot,max_contact_s,max_robot_contact_s,claims,"
                + "double_claims,charger_waits,longest_charger_wait_s,batteries_empty,success,reason,battery_min\n");
        for (Row r : rows) {
            if (r.crashed()) {
                sb.append(String.format(Locale.ROOT, "%s,%d,%s,%d,0,,,,,,,,,false,\"%s\",%n", r.world(), r.robots(),
                        r.controller(), r.seed(), ("crash: " + r.crash()).replace("\"", "\"\"")));
                continue;
            }
            var o = r.outcome();
            String per = o.robots().stream().map(s -> Integer.toString(s.deliveries())).collect(Collectors.joining(" "));
            double contact = o.robots().stream().mapToDouble(RunSummary::contactTime).max().orElse(0);
            // each robot's lowest energy, J: a battery near empty shows before one runs empty
            String lowest = o.robots().stream().map(s -> s.batteryMin() == null ? "-" : String.format(Locale.ROOT, "%.0f", s.batteryMin()))
                    .collect(Collectors.joining(" "));
            sb.append(String.format(Locale.ROOT, "%s,%d,%s,%d,%d,%s,%.1f,%.1f,%d,%d,%d,%.1f,%d,%s,\"%s\",%s%n",
                    r.world(), r.robots(), r.controller(), r.seed(), o.deliveries(), per, contact, o.figures().maxRobotContact(),
                    o.claims(), o.figures().doubleClaims(), o.chargerWaits(), o.figures().longestChargerWait(),
                    o.figures().batteriesEmptied(), success(o), reason(o).replace("\"", "\"\""), lowest));
        }
        return sb.toString();
    }

    /**
     * A table: per controller and team size, the deliveries (per world and seed, in the sweep's
     * order), the ratio to one robot on the same worlds and seeds, how the runs fared on each team
     * criterion, and the criteria met.
     */
    private static String report(List<Row> all, double seconds, WorldGenerator.CylinderRange range) {
        var sb = new StringBuilder("# team-delivery sweep\n\n");
        sb.append(String.format(Locale.ROOT, "%d runs of %.0f simulated seconds%s.%n%n", all.size(), seconds,
                range.equals(WorldGenerator.CylinderRange.TEAM) ? "" : ", worlds of " + range + " cylinders"));
        List<Row> rows = all.stream().filter(r -> !r.crashed()).toList();
        if (rows.size() < all.size()) {
            sb.append(String.format(Locale.ROOT, "%d crashed (left out of the table; their reasons are in runs.csv).%n%n",
                    all.size() - rows.size()));
        }
        sb.append("| controller | robots | runs | deliveries per run | in all | vs one robot | robot contact < 2 s | all contact < 2 s "
                + "| double claims | longest charger wait | runs with a battery empty | criteria met |\n");
        sb.append("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        Map<String, Map<Integer, List<Row>>> by = new LinkedHashMap<>();
        for (Row r : rows) {
            by.computeIfAbsent(r.controller(), k -> new LinkedHashMap<>()).computeIfAbsent(r.robots(), k -> new ArrayList<>()).add(r);
        }
        for (var c : by.entrySet()) {
            List<Row> single = c.getValue().get(1);
            int singleTotal = single == null ? 0 : single.stream().mapToInt(r -> r.outcome().deliveries()).sum();
            boolean agents = c.getKey().equals("agents");
            for (var n : c.getValue().entrySet()) {
                List<Row> rs = n.getValue();
                int total = rs.stream().mapToInt(r -> r.outcome().deliveries()).sum();
                String each = rs.stream().map(r -> Integer.toString(r.outcome().deliveries())).collect(Collectors.joining(", "));
                long robotContact = rs.stream().filter(r -> r.outcome().figures().maxRobotContact() < 2).count();
                long lowContact = rs.stream().filter(r -> r.outcome().robots().stream().allMatch(s -> s.contactTime() < 2)).count();
                int doubles = rs.stream().mapToInt(r -> r.outcome().figures().doubleClaims()).sum();
                double wait = rs.stream().mapToDouble(r -> r.outcome().figures().longestChargerWait()).max().orElse(0);
                long emptied = rs.stream().filter(r -> r.outcome().figures().batteriesEmptied() > 0).count();
                long met = rs.stream().filter(r -> success(r.outcome())).count();
                String ratio = single == null || singleTotal == 0 ? "-" : String.format(Locale.ROOT, "%.2f×", (double) total / singleTotal);
                sb.append(String.format(Locale.ROOT, "| %s | %d | %d | %s | %d | %s | %d of %d | %d of %d | %s | %s | %d | %d of %d |%n",
                        c.getKey(), n.getKey(), rs.size(), each, total, ratio, robotContact, rs.size(), lowContact, rs.size(),
                        agents ? Integer.toString(doubles) : "-", agents ? String.format(Locale.ROOT, "%.0f s", wait) : "-",
                        emptied, met, rs.size()));
            }
        }
        return sb.toString();
    }
}
