package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.robot.Experiment;
import jacabot.robot.run.RunSummary;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a new user meets first: a mistyped option or subcommand gets picocli's suggestion; every error is one "error:" line. */
class NewcomerMessagesTest {
    private static void assertError(String[] r, String code, String text) {
        assertEquals(code, r[0], r[1] + r[2]);
        assertTrue(r[2].startsWith("error: ") && r[2].contains(text), r[2]);
        assertEquals(1, r[2].strip().lines().count(), r[2]);
    }

    @Test
    void aMistypedOptionOrSubcommandGetsADidYouMean() {
        assertError(CliRun.run("experiment", "navigation", "--headles"), "2", "did you mean --headless");
        assertError(CliRun.run("experimnt", "navigation"), "2", "did you mean experiment");
        assertError(CliRun.run("sweep", "navigation", "--seed", "3"), "2", "did you mean --seeds?");
    }

    /** An unknown experiment's list names the team's too, which has its own command line. */
    @Test
    void anUnknownExperimentListsTheTeamToo() {
        assertError(CliRun.run("experiment", "team-deliver"), "2", "; or team-delivery)");
        assertError(CliRun.run("sweep", "team-deliver"), "2", "all or team-delivery)");
    }

    @Test
    void worldRenderErrorsSayError(@TempDir Path dir) {
        assertError(CliRun.run("world", "render", dir.resolve("none.json").toString(), "--out", dir.resolve("x.png").toString()),
                "2", "none.json: $: cannot read the world file");
        assertError(CliRun.run("world", "render", "worlds/navigation.json", "--out", "x.png", "--size", "3"), "2",
                "--size in 50..10000");
        Path txt = dir.resolve("x.txt");
        assertError(CliRun.run("world", "render", "worlds/navigation.json", "--out", txt.toString()), "2",
                "--out " + txt + ": world render writes a PNG; give the file a .png name");
        assertFalse(Files.exists(txt), "nothing written under a name that is not a PNG's");
    }

    @Test
    void aSyntaxErrorIsItsOwnLocatedLine(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.asl");
        Files.writeString(bad, "!start.\n+!start <- foo(.\n");
        String[] r = CliRun.run("experiment", "navigation", "--headless", "--agent", bad.toString(), "--out", dir.resolve("o").toString());
        assertEquals("2", r[0], r[2]);
        assertTrue(r[2].strip().startsWith(bad + ":2:"), "file:line:col first, no 'error: ' before it: " + r[2]);
    }

    @Test
    void aRunOnAnotherWorldOrWithAnotherAgentHasItsOwnFolder() {
        var nav = Experiment.NAVIGATION;
        assertEquals(Path.of("runs/navigation-3"), ExperimentCommand.runFolder(nav, null, null, false, 3));
        assertEquals(Path.of("runs/navigation-3"), ExperimentCommand.runFolder(nav, Path.of("worlds/navigation.json"),
                Path.of("agents/src/main/asl/navigation.asl"), false, 3));
        assertEquals(Path.of("runs/navigation-nav7-1"), ExperimentCommand.runFolder(nav, Path.of("generated/nav7.json"), null, false, 1));
        assertEquals(Path.of("runs/navigation-nav7-my-agent-1"),
                ExperimentCommand.runFolder(nav, Path.of("nav7.json"), Path.of("my-agent.asl"), false, 1));
        assertEquals(Path.of("runs/navigation-as-published-navigation-3"),
                ExperimentCommand.runFolder(nav, null, Path.of("agents/src/main/asl/as-published/navigation.asl"), false, 3));
        assertEquals(Path.of("runs/navigation-baseline-3"), ExperimentCommand.runFolder(nav, null, null, true, 3));
    }

    @Test
    void theSummaryNamesTheWorldAndTheAgentAndTheProgressLineHasNoEmptyBattery(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("o");
        String[] r = CliRun.run("experiment", "obstacle-avoidance", "--headless", "--duration", "11s", "--out", out.toString());
        assertEquals("0", r[0], r[2]);
        String json = Files.readString(out.resolve("summary.json"));
        assertTrue(json.contains("\"worldFile\" : ") && json.contains("worlds/obstacle-avoidance.json"), json);
        assertTrue(json.contains("\"agentFile\" : \"agents/src/main/asl/obstacle-avoidance.asl\""), json);
        assertTrue(Files.readString(out.resolve("summary.txt")).lines().skip(1).findFirst().orElseThrow()
                .matches("files: world .*worlds/obstacle-avoidance.json, agent agents/src/main/asl/obstacle-avoidance.asl"));
        assertTrue(r[1].contains("delivered 0\n") && !r[1].contains("battery"), "no battery in experiment 1:\n" + r[1]);
        assertTrue(r[1].contains(", trajectory.png, steps.jsonl.gz"), r[1]);
        // a summary that names its files still reads back
        RunSummary.fromJson(json);
    }
}
