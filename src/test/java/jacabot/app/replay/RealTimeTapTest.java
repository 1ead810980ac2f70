package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.console.ConsoleLog;
import jacabot.app.console.Verbosity;
import jacabot.app.inspector.MindWatch;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LagMeter;
import jacabot.app.run.RealTimeRun;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A real-time (viewer) run writes the same step log as a headless one: a step per control step, commands, minds. */
class RealTimeTapTest {
    @Test
    void aStepIsTakenFromTheControllersEventLog(@TempDir Path out) throws Exception {
        SimWorld world = SimWorld.of(WorldFileReader.read(RunTapTest.ROOT.resolve(RunTapTest.NAVIGATION.worldFile())));
        var tap = RealTimeTap.open(world, out, RunTapTest.NAVIGATION, "navigation.asl");
        var events = tap.controllerEvents();
        events.accept("step 6 pose -0.2 0.0 0.0"); // before any readings: no step yet
        events.accept("step 7 t=280 CENTRAL_DISTANCE=12.5 GPS=(0.1,0.0,-0.2)");
        events.accept("step 7 apply forward");
        events.accept("step 7 fail-safe no command or heartbeat for 600 ms");
        events.accept("step 7 pose -0.2 0.0 0.0");
        events.accept("step 8 t=320 CENTRAL_DISTANCE=13.0");
        events.accept("step 8 pose -0.2 0.0 0.0");
        assertNull(tap.closeLog());
        try (var reader = new StepLog.Reader(out.resolve(StepLog.FILE))) {
            var first = reader.next();
            assertEquals(280, first.timeMs());
            assertEquals(List.of("forward"), first.commands());
            assertEquals(List.of("CENTRAL_DISTANCE=12.5", "GPS=(0.1,0.0,-0.2)"), first.readings());
            var second = reader.next();
            assertEquals(List.of(), second.commands(), "a step's commands are its own");
            assertNull(reader.next());
        }
    }

    @Test
    void aRealTimeRunWritesAStepPerControlStep(@TempDir Path out) throws Exception {
        var spec = WorldFileReader.read(RunTapTest.ROOT.resolve(RunTapTest.NAVIGATION.worldFile()));
        SimWorld world = SimWorld.of(spec);
        var source = AgentSource.packaged(RunTapTest.NAVIGATION);
        var tap = RealTimeTap.open(world, out, RunTapTest.NAVIGATION, "navigation.asl");
        var console = new ByteArrayOutputStream();
        try (var run = new RealTimeRun(world, RunTapTest.NAVIGATION, source, 3, 2,
                new PrintStream(console, true, StandardCharsets.UTF_8), 0, tap.controllerEvents())) {
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
        // the link's own lines go to the run's console (where the launcher's levels apply), not to stderr:
        // `jacabot bench latency` printed them inside its table
        assertTrue(console.toString(StandardCharsets.UTF_8).contains("[middleware] controller connected: robot 'khepera'"),
                console.toString(StandardCharsets.UTF_8));
        int steps = 0, withCommands = 0, withMind = 0, distances = 0;
        long last = -1;
        try (var reader = new StepLog.Reader(out.resolve(StepLog.FILE))) {
            assertEquals("navigation", reader.header().experiment());
            assertEquals(world.controlStep(), reader.header().controlStep());
            for (StepLog.Step s = reader.next(); s != null; s = reader.next()) {
                assertTrue(last < 0 || s.timeMs() == last + world.controlStep(), "steps in order, none missing: " + last
                        + " then " + s.timeMs());
                last = s.timeMs();
                assertTrue(!s.readings().isEmpty() && s.readings().stream().allMatch(r -> r.contains("=")),
                        "the readings sent, KIND=value: " + s.readings());
                distances += s.readings().stream().anyMatch(r -> r.contains("DISTANCE")) ? 1 : 0;
                steps++;
                withCommands += s.commands().isEmpty() ? 0 : 1;
                withMind += s.mind() == null ? 0 : 1;
            }
        }
        assertTrue(steps >= 8000 / world.controlStep() - 1, "8 simulated seconds, " + steps + " steps");
        assertTrue(distances > 0, "distance readings");
        assertTrue(withCommands > 0, "the agent's commands, as the controller applied them");
        assertTrue(withMind > 0, "the agent's mind, from its samples");
    }

    @Test
    void aRunThatCannotKeepUpSaysSoAndRecordsItsLag(@TempDir Path out) throws Exception {
        SimWorld world = SimWorld.of(WorldFileReader.read(RunTapTest.ROOT.resolve(RunTapTest.NAVIGATION.worldFile())));
        var source = AgentSource.packaged(RunTapTest.NAVIGATION);
        var tap = RealTimeTap.open(world, out, RunTapTest.NAVIGATION, "navigation.asl");
        var statuses = new CopyOnWriteArrayList<String>();
        var console = new ByteArrayOutputStream();
        var warnings = new ByteArrayOutputStream();
        // x100000: a simulated hour per 36 wall-clock ms, more than any machine steps a world over a socket
        try (var run = new RealTimeRun(world, RunTapTest.NAVIGATION, source, 3, 100_000,
                new PrintStream(console, true, StandardCharsets.UTF_8), 0, tap.controllerEvents())) {
            run.lag().addListener(tap.lags()).addListener(new LagMeter.Listener() {
                @Override
                public void started(LagMeter.Reading r) {
                    statuses.add(LagMeter.status(r));
                }

                @Override
                public void ended(LagMeter.Episode e) {
                }
            });
            run.lag().addListener(LagMeter.firstWarning(ConsoleLog.to(
                    new PrintStream(warnings, true, StandardCharsets.UTF_8), Verbosity.NORMAL)::warn));
            run.start();
            run.runner().start();
            long deadline = System.nanoTime() + 60_000_000_000L;
            while (run.lag().episodes().isEmpty() && System.nanoTime() < deadline) {
                Thread.sleep(50);
            }
            Thread.sleep(600); // two more looks: still lagging, no second warning
            assertTrue(run.lag().status().startsWith("LAG: world "), "the status line says so: " + run.lag().status());
            run.lag().close();
            assertTrue(tap.awaitLagNotes(5000), "the episode's end is written with a step");
            run.runner().stop();
            assertNull(tap.closeLog());
        }
        // on a loaded machine the agent may fall behind the world before the world falls behind real time
        assertTrue(!statuses.isEmpty() && statuses.get(0).matches(
                "LAG: (world [0-9.]+ s behind real time \\(×100000 requested|agent [0-9.]+ s behind the world).*"), statuses.toString());
        String warned = warnings.toString(StandardCharsets.UTF_8);
        assertEquals(1, warned.lines().count(), "one warning, not a flood: " + warned);
        assertTrue(warned.startsWith("warning: at t=") && (warned.contains("s behind real time (x100000 requested")
                || warned.contains("s behind the world")), warned);
        var lags = new ArrayList<StepLog.Lag>();
        try (var reader = new StepLog.Reader(out.resolve(StepLog.FILE))) {
            for (StepLog.Step s = reader.next(); s != null; s = reader.next()) {
                if (s.lag() != null) {
                    lags.add(s.lag());
                }
            }
        }
        // one episode, or (loaded machine) an agent episode that ended before the world's began
        assertTrue(!lags.isEmpty() && lags.size() % 2 == 0, lags.toString());
        for (int k = 0; k < lags.size(); k++) {
            assertEquals(k % 2 == 0 ? "start" : "end", lags.get(k).state(), lags.toString());
        }
        StepLog.Lag last = lags.get(lags.size() - 1);
        assertTrue(last.worldBehindMs() > LagMeter.THRESHOLD_MS && last.requested() == 100_000, lags.toString());
    }
}
