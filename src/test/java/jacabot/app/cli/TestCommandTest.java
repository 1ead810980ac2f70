package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jacabot test}: a line per test, the closing count, the exit code, the JUnit report, bad input. */
class TestCommandTest {
    @Test
    void theExampleTestsPass() {
        Path examples = Path.of(System.getProperty("jacabot.rootDir", "."), "examples", "asl-tests");
        String[] r = CliRun.run("test", examples.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        var lines = r[1].lines().toList();
        assertEquals(3, lines.stream().filter(l -> l.startsWith("  passed  counter_test ")).count(), r[1]);
        assertEquals("3 passed, 0 failed", lines.get(lines.size() - 1));
    }

    @Test
    void aFailedAssertionFailsTheRunAndIsReported(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("t.asl"), """
                { include("tester_agent.asl") }
                @[test]
                +!test_one <- !assert_equals(1, 1); !assert_true(false).
                """);
        String[] r = CliRun.run("test", dir.toString(), "--junit", dir.resolve("reports").toString());
        assertEquals("1", r[0], r[1] + r[2]);
        assertTrue(r[1].contains("  FAILED  t test_one assert_true: assert_true on event 'test_one' starting at line 2 FAILED! "
                + "Expected 'false'"), r[1]);
        assertTrue(r[1].endsWith("1 passed, 1 failed\n"), r[1]);
        assertTrue(Files.readString(dir.resolve("reports/TEST-" + dir.resolve("t").toString().replace('/', '.') + ".xml"))
                .contains("failures=\"1\""));
    }

    /** --simulated-time: a minute's wait costs no real time, and the clock the agent reads says a minute went by. */
    @Test
    void simulatedTimeMakesAWaitCostNothing(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("t.asl"), """
                { include("tester_agent.asl") }
                @[test]
                +!test_wait <- .system_time(T0); .wait(60000); .system_time(T1); !assert_equals(60000, T1 - T0).
                """);
        long start = System.nanoTime();
        String[] r = CliRun.run("test", "--simulated-time", dir.toString());
        assertEquals("0", r[0], r[1] + r[2]);
        assertTrue(r[1].contains("  passed  t test_wait assert_equals"), r[1]);
        assertTrue(System.nanoTime() - start < 30_000_000_000L, "well under the minute waited");
    }

    /** A test file that does not read is an ERROR whose every error line stays indented under it. */
    @Test
    void aFileThatDoesNotReadIsAnErrorIndentedUnderItsUnit(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("t.asl"), """
                { include("tester_agent.asl") }
                @[test]
                +!test_a <- !assert_true(true) ?x.
                @[test]
                +!test_b <- !assert_true(true) ?y.
                """);
        String[] r = CliRun.run("test", dir.toString());
        assertEquals("1", r[0], r[1] + r[2]);
        assertTrue(r[1].contains("  ERROR   (run): "), r[1]);
        assertTrue(r[1].lines().filter(l -> l.contains("t.asl:")).allMatch(l -> l.startsWith("  ")), r[1]);
    }

    /** A --junit folder that cannot be made is told first, as a usage error, before any test runs. */
    @Test
    void aJunitFolderThatCannotBeMadeIsAUserError(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("taken"), "a file, not a folder");
        Path examples = Path.of(System.getProperty("jacabot.rootDir", "."), "examples", "asl-tests");
        String[] r = CliRun.run("test", examples.toString(), "--junit", dir.resolve("taken").toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].contains("--junit " + dir.resolve("taken") + ": cannot make the directory (a file of that name exists)"), r[2]);
        assertTrue(r[1].isEmpty(), r[1]);
    }

    @Test
    void noTestsIsAUserError(@TempDir Path dir) {
        String[] r = CliRun.run("test", dir.toString());
        assertEquals("2", r[0], r[1] + r[2]);
        assertTrue(r[2].contains("no AgentSpeak test under"), r[2]);
    }
}
