package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.replay.RunTap;
import jacabot.app.replay.StepLog;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The plots' series collected while the step log is written are the series read back from it. */
class CollectedSeriesTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void collectedDuringTheRunAsReadBack(@TempDir Path dir) throws Exception {
        Experiment navigation = Experiment.parse("navigation").orElseThrow();
        var spec = WorldFileReader.read(ROOT.resolve(navigation.worldFile()));
        var run = new LockstepRun(SimWorld.of(spec), null, navigation, AgentSource.packaged(navigation), 4,
                new PrintStream(OutputStream.nullOutputStream()));
        RunPlots.Series collected;
        try (RunTap tap = RunTap.attach(run, null, dir, navigation, "navigation.asl")) {
            collected = new RunPlots.Series(tap.header());
            tap.onSteps(collected);
            run.runFor(15);
        }
        var read = RunPlots.Series.read(dir.resolve(StepLog.FILE));
        assertTrue(read.t.size() > 300, "steps: " + read.t.size());
        assertFalse(read.selections.isEmpty(), "the agent selected plans");
        assertEquals(read.t, collected.t);
        assertEquals(read.x, collected.x);
        assertEquals(read.z, collected.z);
        assertEquals(read.battery, collected.battery);
        assertEquals(read.left, collected.left);
        assertEquals(read.right, collected.right);
        assertEquals(read.speed, collected.speed);
        assertEquals(read.selections, collected.selections);
        assertEquals(read.markActions, collected.markActions);
        assertEquals(read.start, collected.start);

        RunPlots.writeAll(dir, new PrintStream(OutputStream.nullOutputStream()), collected);
        assertTrue(Files.size(dir.resolve("speed.png")) > 1000);
        assertTrue(Files.size(dir.resolve("events.png")) > 1000);
    }
}
