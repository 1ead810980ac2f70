package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.replay.Replay;
import jacabot.app.replay.RunTap;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Breakpoints in a lockstep run: a breakpoint on a plan label halts at the step the step log of
 * an unpaused run predicts, one step goes one control step on, a cycle step one reasoning cycle
 * (halting between two cycles of a control step), and the run continued writes the
 * same event log and step log, byte for byte, as the run never paused. The agent is the test's
 * own ({@code breaker.asl}), so its labels are known.
 */
class DebuggerTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final Experiment EXPERIMENT = Experiment.parse("obstacle-avoidance").orElseThrow();

    private static String run(Path dir, Debugger debugger) throws Exception {
        String text;
        try (InputStream in = DebuggerTest.class.getResourceAsStream("breaker.asl")) {
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        return run(dir, debugger, "breaker.asl", text, 6);
    }

    private static String run(Path dir, Debugger debugger, String name, String text, double seconds) throws Exception {
        var spec = WorldFileReader.read(ROOT.resolve(EXPERIMENT.worldFile()));
        var run = new LockstepRun(SimWorld.of(spec), null, EXPERIMENT, AgentSource.text(name, text), 1,
                new PrintStream(OutputStream.nullOutputStream()));
        try (RunTap tap = RunTap.attach(run, null, dir, EXPERIMENT, name)) {
            tap.debugger(debugger);
            return run.runFor(seconds).eventLog();
        }
    }

    /** An agent that reasons a few cycles in a row every third control step or so (its waits are 100 ms). */
    static final String TICKER = """
            !tick(0).
            @tick +!tick(N) <- +count(N); -count(N); .wait(100); !tick(N + 1).
            """;

    @Test
    @Timeout(120)
    void eachCycleStepGoesOneCycleAlsoFromAHaltBetweenTwoCycles(@TempDir Path dir) throws Exception {
        var debugger = new Debugger();
        debugger.pause();
        var log = new String[1];
        Thread runner = new Thread(() -> {
            try {
                log[0] = run(dir, debugger, "ticker.asl", TICKER, 2);
            } catch (Exception e) {
                log[0] = "failed: " + e;
            }
        }, "cycle-stepped-run");
        runner.start();
        Debugger.Halt before = await(debugger);
        int betweenCycles = 0;
        for (int k = 0; k < 12; k++) {
            debugger.stepCycle();
            Debugger.Halt next = awaitAfter(debugger, before);
            assertEquals(before.mind().cycle() + 1, next.mind().cycle(),
                    "one cycle on from '" + before.reason() + "' to '" + next.reason() + "'");
            if (!next.reason().contains("the last of this control step")) {
                betweenCycles++;
            }
            before = next;
        }
        assertTrue(betweenCycles >= 2, "some halts are between two cycles of a step, and stepped from: " + betweenCycles);
        debugger.resume();
        runner.join(60_000);
        assertFalse(log[0].startsWith("failed"), log[0]);
    }

    @Test
    @Timeout(180)
    void haltsWhereTheLogPredictsAndAPausedRunIsTheSameRun(@TempDir Path plain, @TempDir Path paused) throws Exception {
        String expected = run(plain, null);
        long predicted = -1;
        for (Replay.Frame f : Replay.open(plain).frames()) {
            if (f.mind().selections().stream().anyMatch(s -> s.plan().startsWith("@drive"))) {
                predicted = f.timeMs();
                break;
            }
        }
        var seen = new TreeSet<String>();
        Replay.open(plain).frames().forEach(f -> f.mind().selections().forEach(x -> seen.add(x.plan())));
        assertTrue(predicted >= 1500, "the plain run selects @drive after its first wait: " + seen + "\n" + expected);

        var debugger = new Debugger();
        debugger.add("label:drive");
        var halts = new CopyOnWriteArrayList<Debugger.Halt>();
        debugger.onHalt(halts::add);
        var log = new String[1];
        Thread runner = new Thread(() -> {
            try {
                log[0] = run(paused, debugger);
            } catch (Exception e) {
                log[0] = "failed: " + e;
            }
        }, "paused-run");
        runner.start();
        Debugger.Halt first = await(debugger);
        assertEquals(predicted, first.timeMs(), "halted at the step the step log predicts: " + first.reason());
        assertTrue(first.reason().contains("@drive"), first.reason());
        Thread.sleep(300); // wall-clock time passes while halted: the simulated world does not move
        debugger.step();
        Debugger.Halt next = awaitAfter(debugger, first);
        assertEquals(predicted + 40, next.timeMs(), "one control step on");
        // one reasoning cycle, twice: the mind one cycle on each time, the world at most one step on
        Debugger.Halt before = next;
        for (int k = 0; k < 2; k++) {
            debugger.stepCycle();
            Debugger.Halt cycle = awaitAfter(debugger, before);
            assertEquals(before.mind().cycle() + 1, cycle.mind().cycle(), "one cycle on: " + cycle.reason());
            assertTrue(cycle.reason().startsWith("one reasoning cycle"), cycle.reason());
            before = cycle;
        }
        debugger.remove("label:drive");
        debugger.resume();
        runner.join(120_000);
        assertEquals(4, halts.size());
        assertEquals(expected, log[0], "the event log of the paused run");
        assertEquals(unzip(plain), unzip(paused), "the step log of the paused run");
    }

    @Test
    void breakpointsMatchLabelsTriggersBeliefsFailuresAndTime() {
        var sel = new MindState.Selection(1000, 10, 1, "+!pick(c1)[source(self)]", "@pickUp +!pick(C) : near(C)", "{C=c1}");
        var fail = new MindState.Selection(1000, 10, 1, "-!go(1)[error(no_applicable)]", "@retry -!go(N)", "{N=1}");
        var mind = new MindState("robot", 1, 1000, 10, List.of(), List.of(), List.of(), List.of(sel, fail));
        assertNotNull(Breakpoint.parse("label:pickUp").hit(mind, List.of(), List.of()));
        assertNull(Breakpoint.parse("label:pick").hit(mind, List.of(), List.of()), "a label is matched whole");
        assertNotNull(Breakpoint.parse("+!pick").hit(mind, List.of(), List.of()));
        assertNotNull(Breakpoint.parse("+!pick(_)").hit(mind, List.of(), List.of()));
        assertNull(Breakpoint.parse("+!pick(c2)").hit(mind, List.of(), List.of()));
        assertNotNull(Breakpoint.parse("failure").hit(mind, List.of(), List.of()));
        assertNotNull(Breakpoint.parse("-battery(_)").hit(mind, List.of(), List.of("battery(low)[source(percept)]")));
        assertNull(Breakpoint.parse("-battery(_)").hit(mind, List.of("battery(low)[source(percept)]"), List.of()));
        assertNotNull(Breakpoint.parse("belief:at(_, 2)").hit(mind, List.of("at(1,2)"), List.of()));
        assertNotNull(Breakpoint.parse("t=1s").hit(mind, List.of(), List.of()));
        assertNull(Breakpoint.parse("t=1.5s").hit(mind, List.of(), List.of()));
        assertEquals(120_000, Breakpoint.parse("t=2m").timeMs());
        var e = assertThrows(IllegalArgumentException.class, () -> Breakpoint.parse("avoidFront"));
        assertTrue(e.getMessage().contains("label:NAME"), e.getMessage());
        var open = assertThrows(IllegalArgumentException.class, () -> Breakpoint.parse("belief:at(_,"));
        assertTrue(open.getMessage().contains("'at(_,': its parentheses or brackets do not close"), open.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Breakpoint.parse("+!pick(c1"));
    }

    /** The console's {@code l} says so when there is no breakpoint left, rather than printing nothing. */
    @Test
    void theConsoleListsBreakpointsOrSaysThereAreNone() {
        var d = new Debugger();
        var bytes = new java.io.ByteArrayOutputStream();
        var out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        DebugConsole.command(d, "l", out);
        assertTrue(bytes.toString(StandardCharsets.UTF_8).contains("no breakpoints"), bytes.toString(StandardCharsets.UTF_8));
        bytes.reset();
        DebugConsole.command(d, "b +!pick", out);
        DebugConsole.command(d, "l", out);
        assertEquals("  breakpoint +!pick\n  +!pick\n", bytes.toString(StandardCharsets.UTF_8).replace("\r", ""));
    }

    /**
     * A {@code label:} breakpoint typed in the console or added from the page is checked against
     * the agent's plan labels as {@code --break label:X} is: one that would never halt the run is
     * refused with the labels nearest to it, and not added.
     */
    @Test
    void aBreakpointOnALabelNoPlanHasIsRefusedFromTheConsoleAndThePage() throws Exception {
        var d = new Debugger();
        d.labels(() -> List.of("drive", "driveOn", "charge"));
        var bytes = new java.io.ByteArrayOutputStream();
        var out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        DebugConsole.command(d, "b label:drve", out);
        DebugConsole.command(d, "b label:charge", out);
        assertEquals("  the agent has no plan labelled @drve (nearest: drive, driveOn, charge)\n  breakpoint label:charge\n",
                bytes.toString(StandardCharsets.UTF_8).replace("\r", ""));
        assertEquals(List.of("label:charge"), d.breakpoints().stream().map(Breakpoint::text).toList());
        var client = java.net.http.HttpClient.newHttpClient();
        try (Inspector inspector = Inspector.startOnFreePort()) {
            inspector.debugger(d);
            var r = client.send(java.net.http.HttpRequest.newBuilder(java.net.URI.create(inspector.url("api/debug?cmd=break&spec=label:chrge")))
                    .POST(java.net.http.HttpRequest.BodyPublishers.noBody()).build(), java.net.http.HttpResponse.BodyHandlers.ofString());
            assertEquals(400, r.statusCode());
            assertEquals("the agent has no plan labelled @chrge (nearest: charge, drive, driveOn)", r.body().trim());
        }
        assertEquals(List.of("label:charge"), d.breakpoints().stream().map(Breakpoint::text).toList());
    }

    private static Debugger.Halt await(Debugger d) throws InterruptedException {
        for (int i = 0; i < 1200 && d.halted() == null; i++) {
            Thread.sleep(50);
        }
        assertNotNull(d.halted(), "the run halted");
        return d.halted();
    }

    private static Debugger.Halt awaitAfter(Debugger d, Debugger.Halt previous) throws InterruptedException {
        for (int i = 0; i < 1200 && (d.halted() == null || d.halted() == previous); i++) {
            Thread.sleep(50);
        }
        assertNotNull(d.halted(), "the run halted again");
        return d.halted();
    }

    private static String unzip(Path dir) throws Exception {
        try (var in = new GZIPInputStream(Files.newInputStream(dir.resolve("steps.jsonl.gz")))) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }
}
