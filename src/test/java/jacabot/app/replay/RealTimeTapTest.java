package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.MindWatch;
import jacabot.app.run.RealTimeRun;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A real-time (viewer) run writes the same step log as a headless one: a step per control step, commands, minds. */
class RealTimeTapTest {
    @Test
    void aRealTimeRunWritesAStepPerControlStep(@TempDir Path out) throws Exception {
        var spec = WorldFileReader.read(RunTapTest.ROOT.resolve(RunTapTest.NAVIGATION.worldFile()));
        SimWorld world = SimWorld.of(spec);
        String source;
        try (InputStream in = RealTimeTapTest.class.getResourceAsStream(RunTapTest.NAVIGATION.agentResource())) {
            source = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        var tap = RealTimeTap.open(world, out, RunTapTest.NAVIGATION, "navigation.asl");
        try (var run = new RealTimeRun(world, RunTapTest.NAVIGATION, source, "navigation.asl", 3, 10,
                new PrintStream(OutputStream.nullOutputStream()), 0, tap.controllerEvents())) {
            var watch = MindWatch.attach(null, run.mas().agent("robot"), null).alsoTo(tap.minds());
            AutoCloseable sampling = MindWatch.sampleEvery(List.of(watch), 50);
            run.start();
            run.runner().start();
            long deadline = System.nanoTime() + 60_000_000_000L;
            while (world.time() < 8 && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            run.runner().stop();
            sampling.close();
            assertNull(tap.closeLog());
        }
        int steps = 0, withCommands = 0, withMind = 0;
        long last = -1;
        try (var reader = new StepLog.Reader(out.resolve(StepLog.FILE))) {
            assertEquals("navigation", reader.header().experiment());
            assertEquals(world.controlStep(), reader.header().controlStep());
            for (StepLog.Step s = reader.next(); s != null; s = reader.next()) {
                assertTrue(last < 0 || s.timeMs() == last + world.controlStep(), "steps in order, none missing: " + last
                        + " then " + s.timeMs());
                last = s.timeMs();
                assertTrue(s.readings().stream().anyMatch(r -> r.startsWith("CENTRAL_DISTANCE=")), s.readings().toString());
                steps++;
                withCommands += s.commands().isEmpty() ? 0 : 1;
                withMind += s.mind() == null ? 0 : 1;
            }
        }
        assertTrue(steps >= 8000 / world.controlStep() - 1, "8 simulated seconds, " + steps + " steps");
        assertTrue(withCommands > 0, "the agent's commands, as the controller applied them");
        assertTrue(withMind > 0, "the agent's mind, from its samples");
    }
}
