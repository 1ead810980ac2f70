package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launcher's failures (docs/reliability.md): each gives one line saying what was wrong and what to do, exit 2
 * for a user error and 1 for a run failure, no stack trace (docs/reliability.md).
 */
class LauncherErrorsTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    private static void assertOneLine(String[] result, String code, String message) {
        assertEquals(code, result[0], result[1] + result[2]);
        assertTrue(result[2].startsWith("error: ") && result[2].contains(message), result[2]);
        assertEquals(1, result[2].strip().lines().count(), "one line: " + result[2]);
        assertFalse(result[2].contains("\tat "), "no stack trace: " + result[2]);
    }

    private static String[] experiment(String... more) {
        String[] args = new String[3 + more.length];
        args[0] = "experiment";
        args[1] = "obstacle-avoidance";
        args[2] = "--headless";
        System.arraycopy(more, 0, args, 3, more.length);
        return CliRun.run(args);
    }

    private static Path world(Path dir, String from, String to) throws Exception {
        String text = Files.readString(ROOT.resolve("worlds/obstacle-avoidance.json"));
        assertTrue(text.contains(from), from);
        Path w = dir.resolve("w.json");
        Files.writeString(w, text.replace(from, to));
        return w;
    }

    @Test
    void anOutputDirectoryThatCannotBeMadeIsToldBeforeTheRun() {
        assertOneLine(experiment("--out", "/dev/null/x", "--duration", "1s"), "2", "--out /dev/null/x: cannot make the directory");
    }

    /** Every command that takes --out tells a place it cannot write as one plain line, without an exception's class. */
    @Test
    void everyOutThatCannotBeMadeIsOnePlainLine() {
        String world = ROOT.resolve("worlds/obstacle-avoidance.json").toString();
        String[][] commands = {
            {"experiment", "team-delivery", "--seed", "1", "--out", "/dev/null/x"},
            {"sweep", "navigation", "--world-seeds", "1", "--seeds", "1", "--jobs", "1", "--no-progress", "--out", "/dev/null/x"},
            {"sweep", "team-delivery", "--world-seeds", "1", "--seeds", "1", "--jobs", "1", "--no-progress", "--out", "/dev/null/x"},
            {"world", "generate", "navigation", "--seed", "1", "--out", "/dev/null/x/w.json"},
            {"world", "render", world, "--seconds", "0", "--out", "/dev/null/x/w.png"},
            {"plot", "a", "b", "--out", "/dev/null/x/o.png"},
        };
        for (String[] c : commands) {
            String[] r = CliRun.run(c);
            assertOneLine(r, "2", "/dev/null/x");
            assertTrue(r[2].contains("(not a directory)") && !r[2].contains("Exception"), String.join(" ", c) + ": " + r[2]);
        }
        assertOneLine(experiment("--out", "/dev/null/x", "--duration", "1s"), "2",
                "--out /dev/null/x: cannot make the directory (not a directory); choose another with --out DIR");
    }

    /** A label no plan has would never halt the run: refused with the labels nearest to it. */
    @Test
    void aBreakOnALabelTheAgentDoesNotHaveIsRefused(@TempDir Path dir) {
        assertOneLine(experiment("--break", "label:coverFrnt", "--duration", "1s", "--out", dir.resolve("o").toString()), "2",
                "--break label:coverFrnt: the agent has no plan labelled @coverFrnt (nearest: coverFront, ");
    }

    @Test
    void agentsThatAreNotPackagedOrClashAreUserErrors(@TempDir Path dir) {
        String out = dir.resolve("o").toString();
        assertOneLine(experiment("--agents", "task,energy", "--out", out), "2",
                "--agents: no packaged agent agents/src/main/asl/obstacle-avoidance-task.asl (suspend-resume has task and energy");
        assertOneLine(CliRun.run("experiment", "suspend-resume", "--agents", "task,task", "--out", out), "2",
                "--agents: 'task' must be a new agent name");
        assertOneLine(CliRun.run("experiment", "suspend-resume", "--agents", "task,energy", "--agent", "x.asl", "--out", out), "2",
                "--agents: not with --agent");
    }

    @Test
    void anAgentThatIsNotAReadableFileIsAUserError(@TempDir Path dir) {
        assertOneLine(experiment("--agent", dir.toString(), "--out", dir.resolve("o").toString()), "2", "no such file");
        assertOneLine(experiment("--agent", dir.resolve("none.asl").toString()), "2", "no such file");
    }

    @Test
    void anUnknownBenchProgramIsAUserError(@TempDir Path dir) throws Exception {
        Path jason = dir.resolve("jason-classpath.txt");
        Files.writeString(jason, "none.jar");
        assertOneLine(CliRun.run("bench", "interpreter", "--jason-classpath", jason.toString(), "--programs", "rules,nope"),
                "2", "--programs: unknown program 'nope'");
    }

    @Test
    void aBenchProjectMustBeAProjectWhoseAgentPrintsStartAndEnd(@TempDir Path dir) throws Exception {
        Path jason = dir.resolve("jason-classpath.txt");
        Files.writeString(jason, dir.resolve("no-jason.jar").toString());
        Files.writeString(dir.resolve("a.asl"), "!g.\n+!g <- .print(start); .print(end); .stopMAS.\n");
        assertOneLine(CliRun.run("bench", "interpreter", "--jason-classpath", jason.toString(), "--project",
                dir.resolve("a.asl").toString()), "2", "--project: " + dir.resolve("a.asl") + ": not a .mas2j file");
        // our interpreter runs the project in its directory; "Jason" here is no Jason at all
        Path project = dir.resolve("p.mas2j");
        Files.writeString(project, "MAS p { agents: a; }\n");
        assertOneLine(CliRun.run("bench", "interpreter", "--jason-classpath", jason.toString(), "--project", project.toString(),
                "--runs", "1"), "1", project + ": on Jason, no agent printed its `start` and `end` lines");
        // a project that cannot be measured leaves a row of dashes, and the next ones are still run
        Path other = dir.resolve("q.mas2j");
        Files.writeString(other, "MAS q { agents: a; }\n");
        String[] both = CliRun.run("bench", "interpreter", "--jason-classpath", jason.toString(), "--project", project.toString(),
                "--project", other.toString(), "--runs", "1");
        assertOneLine(both, "1", project + ": on Jason, no agent printed");
        assertTrue(both[2].contains(other + ": on Jason, no agent printed"), both[2]);
        assertTrue(both[1].contains("| p.mas2j | – |") && both[1].contains("| q.mas2j | – |"), both[1]);
    }

    @Test
    void realTimeWithALockstepOptionIsAUserError(@TempDir Path dir) {
        String out = dir.resolve("o").toString();
        assertOneLine(experiment("--real-time", "--lockstep", "--out", out), "2",
                "--real-time runs one agent with the world in this process; --lockstep is for lockstep runs: drop one of them");
        assertOneLine(experiment("--real-time", "--break", "t=1s", "--out", out), "2", "--break is for lockstep runs");
        assertOneLine(experiment("--real-time", "--baseline", "--out", out), "2", "--baseline is for lockstep runs");
        assertOneLine(experiment("--real-time", "--remote-controller", "--out", out), "2", "--remote-controller is for lockstep runs");
    }

    /** The baseline reads no agent: --agent with it was ignored (or, naming no file, said the file was missing). */
    @Test
    void anAgentWithTheBaselineIsAUserError() {
        String both = "--agent: not with --baseline (the baseline is the procedural controller, no agent): drop one of them";
        assertOneLine(experiment("--baseline", "--agent", "agents/src/main/asl/navigation.asl"), "2", both);
        assertOneLine(experiment("--baseline", "--agent", "no-such-agent.asl"), "2", both);
        assertOneLine(CliRun.run("experiment", "team-delivery", "--baseline", "--agent", "no-such-agent.asl"), "2", both);
        assertOneLine(CliRun.run("experiment", "team-delivery", "--baseline", "--agent", "agents/src/main/asl/team-delivery.asl"),
                "2", both);
    }

    @Test
    void badNumbersAreUserErrors() {
        assertOneLine(CliRun.run("bench", "latency", "--duration", "abc"), "2", "--duration: bad duration 'abc'");
        assertOneLine(CliRun.run("compare", "--duration", "abc"), "2", "--duration: bad duration");
        assertOneLine(experiment("--speed", "-1"), "2", "--speed must be a positive number");
        assertOneLine(experiment("--port", "70000"), "2", "--port must be in 0..65535");
        assertOneLine(experiment("--duration", "soon"), "2", "bad duration");
        // no time at all: the agents' run waited for ever, the baseline's and the team's failed drawing empty plots
        assertOneLine(experiment("--duration", "0s"), "2", "--duration: must be more than 0, got '0s' (examples: 90s, 10m, 1h)");
        assertOneLine(experiment("--duration", "0s", "--baseline"), "2", "--duration: must be more than 0");
        assertOneLine(CliRun.run("experiment", "team-delivery", "--robots", "1", "--duration", "0m"), "2",
                "--duration: must be more than 0");
        // an empty list of names said so, not an IndexOutOfBoundsException
        assertOneLine(CliRun.run("experiment", "suspend-resume", "--agents", ",,"), "2",
                "--agents: no agent named (suspend-resume has task and energy: --agents task,energy)");
        assertOneLine(CliRun.run("experiment", "navigation", "--seed", "x"), "2", "--seed");
    }

    @Test
    void aWorldThatCannotRunIsAUserError(@TempDir Path dir) throws Exception {
        Path huge = world(dir, "\"controlStep\": 40", "\"controlStep\": 1099511627776");
        var r = experiment("--world", huge.toString(), "--out", dir.resolve("o").toString(), "--duration", "1s");
        assertEquals("2", r[0], r[2]);
        assertFalse(r[2].contains("\tat "), r[2]);
        assertEquals(1, r[2].strip().lines().count(), r[2]);
        Path empty = dir.resolve("empty.json");
        Files.writeString(empty, Files.readString(ROOT.resolve("worlds/obstacle-avoidance.json"))
                .replaceAll("(?s)\"robots\": \\[.*?\\n  \\]", "\"robots\": []"));
        var e = experiment("--world", empty.toString(), "--out", dir.resolve("o2").toString(), "--duration", "1s");
        assertEquals("2", e[0], e[1] + e[2]);
        assertTrue(e[2].contains("robot"), e[2]);
        assertFalse(e[2].contains("\tat "), e[2]);
    }

    @Test
    void aPortInUseIsARunFailureWithWhatToDo(@TempDir Path dir) throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            String port = String.valueOf(taken.getLocalPort());
            assertOneLine(experiment("--port", port, "--duration", "1s", "--out", dir.toString()), "1",
                    "cannot listen on port " + port);
            Path mas = ROOT.resolve("agents/src/main/asl/obstacle-avoidance.mas2j");
            assertOneLine(CliRun.run("run", mas.toString(), "--port", port), "1", "port " + port + " is in use");
        }
    }

    @Test
    void anExperimentWritesItsOutputsAndLinkLog(@TempDir Path dir) throws Exception {
        var r = experiment("--duration", "2s", "--out", dir.toString(), "--link-log");
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("Written: "), r[1]);
        long steps = Files.readAllLines(dir.resolve("link-log.txt")).stream().filter(l -> l.matches("step \\d+ t=.*")).count();
        assertEquals(50, steps, "one reading line per control step of 40 ms, streamed to the file");
    }

    @Test
    void aSyntaxErrorInAnAgentIsPrintedOnceWithItsPlace(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.asl");
        Files.writeString(bad, "!g.\n+!g <- .print(a)).\n");
        String[] r = CliRun.run("run", bad.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].startsWith(bad + ":2:17: error: unexpected ')'"), r[2]);
        assertFalse(r[2].contains("error: " + bad), "no second 'error: ' before the place: " + r[2]);
    }
}
