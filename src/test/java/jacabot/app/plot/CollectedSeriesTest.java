package jacabot.app.plot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
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
        assertTrue(read.size() > 300, "steps: " + read.size());
        assertArrayEquals(read.t.values(), collected.t.values());
        assertArrayEquals(read.x.values(), collected.x.values());
        assertArrayEquals(read.z.values(), collected.z.values());
        assertArrayEquals(read.battery.values(), collected.battery.values());
        assertArrayEquals(read.left.values(), collected.left.values());
        assertArrayEquals(read.right.values(), collected.right.values());
        assertArrayEquals(read.speed.values(), collected.speed.values());
        assertEquals(read.selectionMarks, collected.selectionMarks);
        assertEquals(read.markActions, collected.markActions);
        assertEquals(read.start, collected.start);

        RunPlots.writeAll(dir, new PrintStream(OutputStream.nullOutputStream()), collected);
        assertTrue(Files.size(dir.resolve("speed.png")) > 1000);
        assertTrue(Files.size(dir.resolve("events.png")) > 1000);
    }
}
