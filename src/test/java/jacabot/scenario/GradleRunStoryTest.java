package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.replay.ProgressStretch;
import jacabot.app.replay.StepLog;
import jacabot.app.scenario.Scenario;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Robustness: {@code gradle run} (experiment 4, the world's seed 13, 10 simulated minutes) tells the
 * whole story: at least 2 deliveries, a low-battery episode with recharge and return, and no stretch
 * of more than 30 s without progress ({@link ProgressStretch}). Measured: deliveries at 29.3 s and
 * 193.5 s, longest stretch 24.2 s (78.0-102.2 s, on the charger).
 */
class GradleRunStoryTest {
    @Test
    void theDefaultRunTellsTheWholeStory(@TempDir Path dir) throws Exception {
        var r = Scenario.of("suspend-resume").duration(Duration.ofMinutes(10)).out(dir).run();
        String story = String.join("\n", r.console());
        assertTrue(r.summary().deliveries() >= 2, r.summary().toText());
        assertTrue(r.summary().storageEntriesEmpty() == 0, r.summary().toText());
        int low = story.indexOf("Battery low!"), recharged = story.indexOf("RECHARGED"), back = story.indexOf("Previous pt reached");
        assertTrue(low >= 0 && recharged > low && back > recharged, story);
        var stretch = ProgressStretch.longest(dir.resolve(StepLog.FILE), 0.1);
        assertTrue(stretch.seconds() <= 30, "no progress from " + stretch.fromS() + " to " + stretch.toS() + " s");
    }

    /**
     * Nor does one that never moves towards the target it believes: the step log's key steps (every
     * 4 s) list the whole mind, its target too, which is no new target.
     */
    @Test
    void aRobotThatStandsStillBesideItsTargetMakesNoProgress(@TempDir Path dir) throws Exception {
        assertStandsStill(dir, "targetPoint(0.4, -0.4).\n");
    }

    /** The measure can fail: an agent that never moves makes no progress at all. */
    @Test
    void aRobotThatStandsStillMakesNoProgress(@TempDir Path dir) throws Exception {
        assertStandsStill(dir, "");
    }

    /** Runs 40 s of an agent that believes {@code beliefs} and never moves: no progress in all of it. */
    private static void assertStandsStill(Path dir, String beliefs) throws Exception {
        Path idle = dir.resolve("idle.asl");
        Files.writeString(idle, beliefs + "!start.\n+!start <- .print(\"standing still\").\n");
        Scenario.of("suspend-resume").agent(idle).duration(Duration.ofSeconds(40)).out(dir.resolve("run")).run();
        var stretch = ProgressStretch.longest(dir.resolve("run").resolve(StepLog.FILE), 0.1);
        assertTrue(stretch.seconds() >= 39, stretch.toString());
    }
}
