package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.scenario.Scenario;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jacabot replay} and {@code jacabot plot} headless, on a run recorded through the Scenario API. */
class ReplayCommandTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void replaysARecordedRunHeadless(@TempDir Path dir) throws Exception {
        Path run = dir.resolve("run");
        var result = Scenario.of("navigation").world(ROOT.resolve("worlds/navigation.json")).seed(2)
                .duration(Duration.ofSeconds(5)).out(run).run();
        assertTrue(Files.isRegularFile(run.resolve("steps.jsonl.gz")), result.eventLog());
        assertTrue(Files.isRegularFile(run.resolve("battery.png")));

        String[] r = CliRun.run("replay", run.toString(), "--headless", "--at", "3s", "--frames", "2");
        assertEquals("0", r[0], r[2]);
        assertTrue(r[1].contains("experiment navigation") && r[1].contains("seed 2"), r[1]);
        assertTrue(r[1].contains("Mind at t=3.00 s"), r[1]);
        assertTrue(r[1].matches("(?s).*intentions:\\R\\s+intention \\d+ .*"), r[1]); // which ones run at 3 s is the agent's business
        assertTrue(Files.isRegularFile(run.resolve("frames/frame-0002.png")), r[1]);

        String[] after = CliRun.run("replay", run.toString(), "--headless", "--at", "9s");
        assertEquals("2", after[0], after[1]);
        assertTrue(after[2].contains("--at 9s: after the run's end (5.0 s simulated)") && after[1].isEmpty(), after[2]);
        String[] bad = CliRun.run("replay", run.toString(), "--headless", "--at", "soon");
        assertEquals("2", bad[0], bad[1]);
        assertTrue(bad[2].contains("--at: bad duration 'soon'") && bad[1].isEmpty(), bad[2]);
        assertTrue(CliRun.run("replay", run.toString(), "--headless", "--at", "5s")[1].contains("Mind at t=4.96 s"));
        assertEquals("2", CliRun.run("replay", run.toString(), "--headless", "--frames", "-1")[0]);

        Files.delete(run.resolve("speed.png"));
        String[] p = CliRun.run("plot", run.toString());
        assertEquals("0", p[0], p[2]);
        assertTrue(Files.isRegularFile(run.resolve("speed.png")));
    }

    @Test
    void aFolderWithoutStepLogIsAUsageError(@TempDir Path dir) throws Exception {
        String[] r = CliRun.run("replay", dir.toString(), "--headless");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("no step log"), r[2]);
        Files.write(dir.resolve("steps.jsonl.gz"), "not gzip".getBytes());
        r = CliRun.run("replay", dir.toString(), "--headless");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("steps.jsonl.gz"), r[2]);
        assertEquals("2", CliRun.run("plot", dir.resolve("nothing").toString())[0]);
    }
}
