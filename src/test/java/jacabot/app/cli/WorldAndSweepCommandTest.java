package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.console.ConsoleLog;
import jacabot.app.console.Verbosity;
import jacabot.app.sweep.RunOutcome;
import jacabot.app.sweep.SuccessCriteria;
import jacabot.app.sweep.SweepRun;
import jacabot.robot.Experiment;
import jacabot.sim.io.WorldFileReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jacabot world ...}, {@code jacabot sweep ...} and the landmark check of {@code jacabot experiment}. */
class WorldAndSweepCommandTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void generateWritesAWorldTheLoaderAccepts(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("w.json");
        var r = CliRun.run("world", "generate", "navigation", "--seed", "4", "--out", file.toString());
        assertEquals("0", r[0], r[2]);
        assertEquals("navigation-gen-4", WorldFileReader.read(file).name());
        var again = CliRun.run("world", "generate", "3", "--seed", "4");
        assertEquals(Files.readString(file), again[1]);
        assertEquals("2", CliRun.run("world", "generate", "flying", "--seed", "1")[0]);
        assertEquals("2", CliRun.run("world", "generate", "navigation")[0]); // no seed
    }

    @Test
    void generateMakesTeamWorlds(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("team.json");
        var r = CliRun.run("world", "generate", "team-delivery", "--robots", "3", "--seed", "4", "--out", file.toString());
        assertEquals("0", r[0], r[2]);
        assertEquals(3, WorldFileReader.read(file).robots().size());
        var tooMany = CliRun.run("world", "generate", "team-delivery", "--robots", "9", "--seed", "4");
        assertEquals("2", tooMany[0]);
        assertEquals("error: --robots must be 1 to 8, got 9", tooMany[2].strip());
        var notATeam = CliRun.run("world", "generate", "navigation", "--robots", "2", "--seed", "4");
        assertEquals("2", notATeam[0]);
        assertEquals("error: --robots is for team-delivery only; navigation has one robot", notATeam[2].strip());
        assertEquals("error: unknown experiment 'flying' (expected one of obstacle-avoidance, object-picking, navigation, "
                + "suspend-resume, tidy-up, team-delivery)", CliRun.run("world", "generate", "flying", "--seed", "1")[2].strip());
    }

    @Test
    void aTeamWorldsCylindersComeInTheRangeAskedTheDefaultRangeKeepingEveryWorld(@TempDir Path dir) throws Exception {
        var plain = CliRun.run("world", "generate", "team-delivery", "--robots", "4", "--seed", "80");
        var asDefault = CliRun.run("world", "generate", "team-delivery", "--robots", "4", "--seed", "80", "--cylinders", "10..14");
        assertEquals("0", asDefault[0], asDefault[2]);
        assertEquals(plain[1], asDefault[1]); // the same draw: the worlds measured so far stay as they were
        for (long seed = 1; seed <= 4; seed++) {
            Path file = dir.resolve("more-" + seed + ".json");
            var more = CliRun.run("world", "generate", "team-delivery", "--robots", "4", "--seed", Long.toString(seed),
                    "--cylinders", "20..24", "--out", file.toString());
            assertEquals("0", more[0], more[2]);
            int n = WorldFileReader.read(file).cylinders().size();
            assertTrue(n >= 20 && n <= 24, "world " + seed + ": " + n + " cylinders");
        }
        var backwards = CliRun.run("world", "generate", "team-delivery", "--seed", "1", "--cylinders", "14..10");
        assertEquals("2", backwards[0]);
        assertEquals("error: --cylinders: cylinders must be a range MIN..MAX with 1 <= MIN <= MAX <= 60, got 14..10",
                backwards[2].strip());
        assertEquals("error: --cylinders: 'many' is not a range of cylinders (examples: 10..14, 20..24, 16)",
                CliRun.run("world", "generate", "team-delivery", "--seed", "1", "--cylinders", "many")[2].strip());
        var sweep = CliRun.run("sweep", "team-delivery", "--robots", "1", "--world-seeds", "1", "--seeds", "1", "--duration", "2s",
                "--controllers", "baseline", "--cylinders", "20..24", "--out", dir.toString());
        assertEquals("0", sweep[0], sweep[2]);
        assertTrue(Files.readString(dir.resolve("report.md")).contains("1 runs of 2 simulated seconds, worlds of 20..24 cylinders."));
        assertEquals("error: --cylinders is for team-delivery only",
                CliRun.run("world", "generate", "navigation", "--seed", "1", "--cylinders", "3")[2].strip());
    }

    @Test
    void aTeamSweepTakesNoProgressAsTheSingleRobotSweepDoes(@TempDir Path dir) {
        String[] args = {"sweep", "team-delivery", "--robots", "1", "--world-seeds", "1", "--seeds", "1", "--duration", "4s",
            "--controllers", "baseline", "--out", dir.toString()};
        var withLines = CliRun.run(args);
        assertEquals("0", withLines[0], withLines[2]);
        assertTrue(withLines[1].contains("world 1 seed 1, 1 robot, baseline:"), withLines[1]);
        String[] quiet = Arrays.copyOf(args, args.length + 1);
        quiet[args.length] = "--no-progress";
        var without = CliRun.run(quiet);
        assertEquals("0", without[0], without[2]);
        assertFalse(without[1].contains("world 1 seed 1"), without[1]);
        assertTrue(without[1].contains("Written: "), without[1]);
    }

    @Test
    void aTeamSweepKeepsEachAgentsRunsLogsWhenAsked(@TempDir Path dir) throws Exception {
        var r = CliRun.run("sweep", "team-delivery", "--robots", "2", "--world-seeds", "3", "--seeds", "1", "--duration", "4s",
                "--controllers", "agents", "--logs", "--no-progress", "--out", dir.toString());
        assertEquals("0", r[0], r[2]);
        Path run = dir.resolve("logs").resolve("3-2r-s1");
        List<String> console = Files.readAllLines(run.resolve("console.txt"));
        assertFalse(console.isEmpty());
        // every line after the simulated time it was printed at, never beyond the run's 4 s
        for (String line : console) {
            assertTrue(line.matches("t=\\d\\.\\d\\d .*"), line);
        }
        List<String> world = Files.readAllLines(run.resolve("world.txt"));
        assertTrue(world.get(0).startsWith("arena "), world.get(0));
        assertTrue(world.stream().anyMatch(l -> l.startsWith("cylinder ")), world.toString());
        assertTrue(Files.exists(run.resolve("events.txt")));
        String header = Files.readAllLines(dir.resolve("runs.csv")).get(0);
        assertTrue(header.endsWith(",battery_min"), header);
        String row = Files.readAllLines(dir.resolve("runs.csv")).get(1);
        assertTrue(row.matches(".*,\\d+ \\d+$"), row); // both robots' lowest energy
    }

    @Test
    void aTeamSweepWritesARowPerRunAndACrashAsARow(@TempDir Path dir) throws Exception {
        var r = CliRun.run("sweep", "team-delivery", "--robots", "1,2", "--world-seeds", "1", "--seeds", "1", "--duration", "3s",
                "--controllers", "baseline", "--jobs", "2", "--no-progress", "--out", dir.toString());
        assertEquals("0", r[0], r[2]);
        var lines = Files.readAllLines(dir.resolve("runs.csv"));
        assertEquals(3, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(1).startsWith("team-delivery-gen-1,1,baseline,1,"), lines.get(1));
        assertTrue(lines.get(2).startsWith("team-delivery-gen-1,2,baseline,1,"), lines.get(2));
        assertFalse(Files.exists(dir.resolve("runs.csv.part")));
        String crash = TeamSweepCommand.csv(List.of(
                new TeamSweepCommand.Row("team-delivery-gen-7", 4, "agents", 2, null, "IllegalStateException: \"no robot\" at TeamLockstepRun.step:12")));
        assertEquals("team-delivery-gen-7,4,agents,2,0,,,,,,,,,false,\"crash: IllegalStateException: \"\"no robot\"\" at "
                + "TeamLockstepRun.step:12\",", crash.lines().skip(1).findFirst().orElseThrow());
    }

    @Test
    void aTeamSweepRunsAFoldersTeamWorldFilesAndRejectsABadOneBeforeAnyRun(@TempDir Path dir) throws Exception {
        Path worlds = Files.createDirectories(dir.resolve("worlds"));
        Files.copy(ROOT.resolve("worlds/team-delivery.json"), worlds.resolve("mine.json"));
        var r = CliRun.run("sweep", "team-delivery", "--worlds", worlds.toString(), "--robots", "1,2", "--seeds", "1",
                "--duration", "3s", "--controllers", "baseline", "--no-progress", "--out", dir.resolve("out").toString());
        assertEquals("0", r[0], r[2]);
        var lines = Files.readAllLines(dir.resolve("out/runs.csv"));
        assertEquals(3, lines.size(), String.join("\n", lines));
        assertTrue(lines.get(1).startsWith("mine,1,baseline,1,"), lines.get(1));
        assertTrue(lines.get(2).startsWith("mine,2,baseline,1,"), lines.get(2));
        Files.writeString(worlds.resolve("torn.json"), "{ \"name\": \"torn\",\n");
        var bad = CliRun.run("sweep", "team-delivery", "--worlds", worlds.toString(), "--robots", "2", "--seeds", "1",
                "--duration", "3s", "--out", dir.resolve("bad").toString());
        assertEquals("2", bad[0]);
        assertEquals(1, bad[2].strip().lines().count(), bad[2]);
        assertTrue(bad[2].contains("torn.json") && bad[2].contains("line 2"), bad[2]);
        assertFalse(Files.exists(dir.resolve("bad")));                  // nothing written
        var both = CliRun.run("sweep", "team-delivery", "--worlds", worlds.toString(), "--world-seeds", "1");
        assertEquals("2", both[0]);
    }

    @Test
    void renderDrawsAPng(@TempDir Path dir) {
        Path png = dir.resolve("w.png");
        var r = CliRun.run("world", "render", ROOT.resolve("worlds/navigation.json").toString(), "--out", png.toString(),
                "--seconds", "2", "--size", "200");
        assertEquals("0", r[0], r[2]);
        assertTrue(Files.isRegularFile(png));
        var bad = CliRun.run("world", "render", dir.resolve("none.json").toString(), "--out", png.toString());
        assertEquals("2", bad[0]);
        assertEquals(1, bad[2].strip().lines().count(), bad[2]);
    }

    @Test
    void anUnknownFieldIsNamedWithItsJsonPath(@TempDir Path dir) throws Exception {
        String text = Files.readString(ROOT.resolve("worlds/navigation.json")).replace("\"radius\": 0.06", "\"radius\": 0.06, \"colour\": 1");
        Path file = dir.resolve("bad.json");
        Files.writeString(file, text);
        var r = CliRun.run("experiment", "navigation", "--world", file.toString(), "--headless", "--duration", "1s");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("$.storage") && r[2].contains("colour"), r[2]);
        assertFalse(r[2].contains("\tat "), r[2]);
    }

    @Test
    void aMissingLandmarkStopsAgentAndBaselineBeforeTheRun(@TempDir Path dir) throws Exception {
        String text = Files.readString(ROOT.resolve("worlds/suspend-resume.json"))
                .replaceAll("\"charger\": \\{[^}]*\\},\\s*", "");
        Path file = dir.resolve("nocharger.json");
        Files.writeString(file, text);
        for (String[] args : new String[][] {
                {"experiment", "suspend-resume", "--world", file.toString(), "--headless", "--duration", "5s", "--out", dir.toString()},
                {"experiment", "suspend-resume", "--world", file.toString(), "--baseline", "--duration", "5s", "--out", dir.toString()}}) {
            var r = CliRun.run(args);
            assertEquals("2", r[0], r[1] + r[2]);
            assertEquals("error: " + file + ": $.charger: the suspend-resume experiment needs a charger; the world has none",
                    r[2].strip());
            assertFalse(r[1].contains("t=  "), "no run started: " + r[1]);
        }
        Path nav = dir.resolve("nostorage.json");
        Files.writeString(nav, Files.readString(ROOT.resolve("worlds/navigation.json")).replaceAll("\"storage\": \\{[^}]*\\},\\s*", ""));
        var r = CliRun.run("experiment", "navigation", "--world", nav.toString(), "--baseline", "--duration", "5s");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("$.storage: the navigation experiment needs a storage point"), r[2]);
    }

    @Test
    void sweepShardsMergeIntoOneReport(@TempDir Path dir) throws Exception {
        Path worlds = dir.resolve("worlds");
        Files.createDirectories(worlds);
        Files.copy(ROOT.resolve("worlds/object-picking.json"), worlds.resolve("object-picking.json"));
        for (int i = 1; i <= 2; i++) {
            var r = CliRun.run("sweep", "object-picking", "--worlds", worlds.toString(), "--seeds", "1..2", "--duration", "3s",
                    "--jobs", "2", "--shard", i + "/2", "--out", dir.resolve("s" + i).toString(), "--no-progress");
            assertEquals("0", r[0], r[2]);
            assertEquals(3, Files.readAllLines(dir.resolve("s" + i).resolve("runs.csv")).size(), "header + 2 of the 4 runs");
        }
        var m = CliRun.run("sweep", "merge", dir.resolve("s1").toString(), dir.resolve("s2").toString(), "--out",
                dir.resolve("all").toString());
        assertEquals("0", m[0], m[2]);
        var rows = Files.readAllLines(dir.resolve("all").resolve("runs.csv"));
        assertEquals(5, rows.size(), String.join("\n", rows));
        String report = Files.readString(dir.resolve("all").resolve("report.md"));
        assertTrue(report.contains("| agent | 2 |") && report.contains("| baseline | 2 |"), report);
        assertTrue(report.contains("no cylinder picked"), "3 s is too short to pick: " + report);
    }

    /** Tidy-up: generated worlds of chosen generator seeds (--world-seeds), the agent only (it has no baseline). */
    @Test
    void sweepTidyUpOnChosenGeneratorSeeds(@TempDir Path dir) throws Exception {
        var r = CliRun.run("sweep", "tidy-up", "--world-seeds", "51,52", "--seeds", "1", "--duration", "2s",
                "--out", dir.toString(), "--no-progress");
        assertEquals("0", r[0], r[2]);
        var rows = Files.readAllLines(dir.resolve("runs.csv"));
        assertEquals(3, rows.size(), rows.toString()); // the header, the agent on each world; no baseline
        assertTrue(rows.get(1).startsWith("tidy-up,tidy-up-gen-51,agent,") && rows.get(2).startsWith("tidy-up,tidy-up-gen-52,agent,"),
                rows.toString());
        assertTrue(rows.get(1).contains("cylinders in the storage area") && rows.get(1).contains("not parked on the charger"), rows.get(1));
        assertEquals("2", CliRun.run("sweep", "tidy-up", "--world-seeds", "51", "--generate", "3")[0]);
        assertEquals("2", CliRun.run("experiment", "tidy-up", "--baseline", "--duration", "1s")[0]);
    }

    @Test
    void sweepRunsTheAgentGivenWithAgent(@TempDir Path dir) throws Exception {
        Path worlds = dir.resolve("worlds");
        Files.createDirectories(worlds);
        Files.copy(ROOT.resolve("worlds/obstacle-avoidance.json"), worlds.resolve("obstacle-avoidance.json"));
        Path agent = dir.resolve("idle.asl");
        Files.writeString(agent, "!start.\n+!start <- .print(\"an idle agent of my own\").\n");
        var r = CliRun.run("sweep", "obstacle-avoidance", "--agent", agent.toString(), "--worlds", worlds.toString(),
                "--seeds", "1", "--duration", "3s", "--controllers", "agent", "--out", dir.resolve("s").toString(), "--no-progress");
        assertEquals("0", r[0], r[2]);
        String console = Files.readString(dir.resolve("s/logs/obstacle-avoidance_obstacle-avoidance_agent_seed1.failure.txt"));
        assertTrue(console.contains("an idle agent of my own"), console);

        Files.writeString(agent, "+!start <- .print(\n");
        var bad = CliRun.run("sweep", "obstacle-avoidance", "--agent", agent.toString(), "--worlds", worlds.toString(),
                "--out", dir.resolve("t").toString());
        assertEquals("2", bad[0]);
        // file:line:col where the '(' should have closed: the end of the file, on line 2
        assertTrue(bad[2].startsWith(agent + ":2:1: error: expected ')'"), bad[2]);
        assertEquals("2", CliRun.run("sweep", "all", "--agent", agent.toString(), "--out", dir.toString())[0]);
    }

    @Test
    void sweepUsageErrorsExitWith2(@TempDir Path dir) {
        assertEquals("2", CliRun.run("sweep", "flying")[0]);
        assertEquals("2", CliRun.run("sweep", "all", "--shard", "3/2", "--out", dir.toString())[0]);
        assertEquals("2", CliRun.run("sweep", "all", "--seeds", "x", "--out", dir.toString())[0]);
        assertEquals("2", CliRun.run("sweep", "merge", dir.resolve("none").toString())[0]);
    }

    @Test
    void aRunThatSucceedsRemovesTheFailureAnEarlierSweepIntoTheSameDirectoryLeft(@TempDir Path logs) throws Exception {
        Path failure = logs.resolve("obstacle-avoidance_w1_agent_seed1.failure.txt");
        Files.writeString(failure, "contact 2.5 s > 2 s (an earlier sweep's run)\n");
        var log = ConsoleLog.to(System.out, Verbosity.QUIET);
        var figures = new SuccessCriteria.Figures(600, 0.1, 0.6, 0, 0, 0, false, 0, 0);
        var ok = new RunOutcome(Experiment.OBSTACLE_AVOIDANCE, "w1", "agent", 1,
                RunOutcome.OK, true, "", 600, 1, figures, 0, 0);
        SweepCommand.writeLogs(logs, new SweepRun.Result(ok, "events\n", List.of()), log);
        assertFalse(Files.exists(failure), "the earlier sweep's failure is gone");
        assertEquals("events\n", Files.readString(logs.resolve("obstacle-avoidance_w1_agent_seed1.events.txt")));
        var failed = new RunOutcome(Experiment.OBSTACLE_AVOIDANCE, "w1", "agent", 1,
                RunOutcome.OK, false, "contact 3.0 s > 2 s", 600, 1, figures, 0, 0);
        SweepCommand.writeLogs(logs, new SweepRun.Result(failed, "events\n", List.of("last")), log);
        assertTrue(Files.readString(failure).startsWith("contact 3.0 s > 2 s"), Files.readString(failure));
    }
}
