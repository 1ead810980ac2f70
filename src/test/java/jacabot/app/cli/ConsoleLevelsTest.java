package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The console's levels: --quiet, the default and --verbose; repeated agent lines folded; warnings on mix-ups. */
class ConsoleLevelsTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    /** The thesis' agent as published: near a wall it prints "Obstacle: N", "Wait avoiding", "high left" in a loop. */
    private static final String PUBLISHED = ROOT.resolve("agents/src/main/asl/as-published/suspend-resume.asl").toString();

    private static String[] published(Path out, String... level) {
        var args = new ArrayList<>(List.of("experiment", "suspend-resume", "--headless", "--duration", "40s",
                "--agent", PUBLISHED, "--out", out.toString()));
        args.addAll(List.of(level));
        String[] r = CliRun.run(args.toArray(new String[0]));
        assertEquals("0", r[0], r[1] + r[2]);
        return r;
    }

    private static long count(String text, String line) {
        return text.lines().filter(line::equals).count();
    }

    @Test
    void theThreeLevels(@TempDir Path dir) {
        String verbose = published(dir.resolve("v"), "--verbose")[1];
        String normal = published(dir.resolve("n"))[1];
        String quiet = published(dir.resolve("q"), "--quiet")[1];
        // the same run three times (lockstep, one seed): only what is shown differs
        long repeats = count(verbose, "[robot] Wait avoiding");
        assertTrue(repeats >= 4, "the published agent loops near the wall:\n" + verbose);
        // by default: shown once per burst (a progress line ends one), then counted; nothing lost
        long shown = count(normal, "[robot] Wait avoiding");
        long folded = normal.lines().filter(l -> l.startsWith("[robot] Wait avoiding (x"))
                .mapToLong(l -> Long.parseLong(l.replaceAll(".*\\(x(\\d+) more\\)", "$1"))).sum();
        assertTrue(shown < repeats && folded > 0, normal);
        assertEquals(repeats, shown + folded, "every repetition counted:\n" + normal);
        assertTrue(normal.lines().count() < verbose.lines().count(), "folded: " + normal.lines().count() + " lines against "
                + verbose.lines().count());
        // the default keeps the story and the progress line
        for (String story : List.of("[robot] Right Cylinder", "[robot] Reach lateral cylinder failed.", "  t=  10.0 s",
                "Experiment 4 (suspend-resume)")) {
            assertTrue(normal.contains(story), story + " missing:\n" + normal);
        }
        // quiet: the summary and the files written, nothing else
        assertFalse(quiet.contains("[robot]"), quiet);
        assertFalse(quiet.contains("t=  10.0 s"), quiet);
        assertTrue(quiet.startsWith("run: suspend-resume, robot khepera, agent, seed 13"), quiet);
        assertTrue(quiet.contains("Written: "), quiet);
        // every level writes the same run, and no link log unless asked for
        for (String d : List.of("v", "n", "q")) {
            assertTrue(Files.isRegularFile(dir.resolve(d).resolve("steps.jsonl.gz")));
            assertFalse(Files.exists(dir.resolve(d).resolve("link-log.txt")), "link-log.txt without --link-log");
        }
    }

    @Test
    void quietAndVerboseTogetherAreAUsageError() {
        String[] r = CliRun.run("experiment", "navigation", "--headless", "--quiet", "--verbose");
        assertEquals("2", r[0]);
        assertTrue(r[2].startsWith("error: --quiet and --verbose exclude each other"), r[2]);
    }

    @Test
    void aLinkLogOnlyWhenAskedForAndSaidWhereItIs(@TempDir Path dir) throws Exception {
        String[] r = CliRun.run("experiment", "obstacle-avoidance", "--headless", "--duration", "2s", "--out",
                dir.toString(), "--link-log");
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("Link log: " + dir.resolve("link-log.txt")), r[1]);
        assertTrue(Files.size(dir.resolve("link-log.txt")) > 0);
    }

    @Test
    void aWorldOrAnAgentOfAnotherExperimentIsWarnedAbout(@TempDir Path dir) {
        String[] world = CliRun.run("experiment", "navigation", "--headless", "--duration", "1s", "--out", dir.toString(),
                "--world", ROOT.resolve("worlds/suspend-resume.json").toString());
        assertEquals("0", world[0], world[2]);
        assertTrue(world[2].contains("warning: " + ROOT.resolve("worlds/suspend-resume.json")
                + " is a world of experiment 4 (suspend-resume), not of navigation"), world[2]);
        String agent = ROOT.resolve("agents/src/main/asl/obstacle-avoidance.asl").toString();
        String[] mixed = CliRun.run("experiment", "navigation", "--headless", "--duration", "1s", "--out", dir.toString(),
                "--agent", agent);
        assertEquals("0", mixed[0], mixed[2]);
        assertTrue(mixed[2].contains("warning: " + agent + " is written for experiment 1 (obstacle-avoidance: it makes the "
                + "ObstacleAvoidanceMiddleware), but runs here with the NavigationMiddleware of navigation"), mixed[2]);
        String[] fine = CliRun.run("experiment", "navigation", "--headless", "--duration", "1s", "--out", dir.toString());
        assertFalse(fine[2].contains("warning"), fine[2]);
        // tidy-up's own agent makes the middleware tidy-up shares with suspend-resume: no mix-up
        String[] tidy = CliRun.run("experiment", "tidy-up", "--headless", "--duration", "1s", "--out", dir.toString());
        assertEquals("0", tidy[0], tidy[2]);
        assertFalse(tidy[2].contains("warning"), tidy[2]);
    }

    @Test
    void aProjectMakingAnotherExperimentsMiddlewareIsWarnedAbout(@TempDir Path dir) throws Exception {
        Files.copy(ROOT.resolve("agents/src/main/asl/suspend-resume.asl"), dir.resolve("robot.asl"));
        Path mas = dir.resolve("navigation.mas2j");
        Files.writeString(mas, "MAS navigation {\n agents: robot robot.asl;\n}\n");
        var warnings = RunCommand.projectWarnings(mas);
        assertEquals(1, warnings.size(), warnings.toString());
        assertTrue(warnings.get(0).contains("the project 'navigation' makes the SuspendResumeMiddleware of experiment 4"),
                warnings.get(0));
        assertEquals(List.of(), RunCommand.projectWarnings(ROOT.resolve("agents/src/main/asl/navigation.mas2j")));
    }

    @Test
    void jacabotRunPrintsEveryLineAsJasonDoesAndNothingWhenQuiet(@TempDir Path dir) throws Exception {
        Path asl = dir.resolve("ticker.asl");
        Files.writeString(asl, "!start.\n+!start <- .print(tick); .print(tick); .print(tick); .print(tick); .print(done); .stopMAS.\n");
        String[] normal = CliRun.run("run", asl.toString());
        assertEquals("0", normal[0], normal[2]);
        // a Jason program's console is compared line for line with Jason's: nothing folded
        assertEquals(List.of("[ticker] tick", "[ticker] tick", "[ticker] tick", "[ticker] tick", "[ticker] done"),
                normal[1].lines().toList());
        String[] verbose = CliRun.run("run", asl.toString(), "--verbose");
        assertEquals(List.of("[ticker] tick", "[ticker] tick", "[ticker] tick", "[ticker] tick", "[ticker] done"),
                verbose[1].lines().toList());
        assertEquals("", CliRun.run("run", asl.toString(), "--quiet")[1]);
    }
}
