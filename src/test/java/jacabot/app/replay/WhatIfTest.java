package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.Debugger;
import jacabot.app.inspector.Inspector;
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
import java.util.ArrayList;
import java.util.List;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A what-if run is the recorded run, byte for byte, up to its instant, and the edited agent's
 * after it (the test's own small agent, {@code breaker.asl}, and its edit {@code breaker-edited.asl}).
 */
class WhatIfTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final Experiment EXPERIMENT = Experiment.parse("obstacle-avoidance").orElseThrow();
    static final long AT = 3_000;

    private static AgentSource agent(String name) throws Exception {
        try (InputStream in = Inspector.class.getResourceAsStream(name)) {
            return AgentSource.text(name, new String(in.readAllBytes(), StandardCharsets.UTF_8));
        }
    }

    private static SimWorld world() throws Exception {
        return SimWorld.of(WorldFileReader.read(ROOT.resolve(EXPERIMENT.worldFile())));
    }

    @Test
    @Timeout(180)
    void sameRunUpToItsInstantThenTheEditedAgents(@TempDir Path recorded, @TempDir Path whatIf) throws Exception {
        var quiet = new PrintStream(OutputStream.nullOutputStream());
        var run = new LockstepRun(world(), null, EXPERIMENT, agent("breaker.asl"), 1, quiet);
        String original;
        try (RunTap tap = RunTap.attach(run, null, recorded, EXPERIMENT, "breaker.asl")) {
            original = run.runFor(6).eventLog();
        }
        var r = WhatIf.run(world(), EXPERIMENT, 1, agent("breaker.asl"), agent("breaker-edited.asl"), AT, 6, whatIf, quiet);
        assertEquals(AT, r.swappedAtMs());
        // its console by simulated time, the swap marked at its instant
        List<String> console = Files.readAllLines(whatIf.resolve(ConsoleFile.FILE));
        assertTrue(console.contains("t=3.000 what-if: the edited agent's plans from here on"), console.toString());
        assertTrue(console.containsAll(r.recorder().events()), "the event log's lines too: " + r.recorder().events() + " in " + console);

        List<String> a = steps(recorded), b = steps(whatIf);
        int upTo = 0;
        while (upTo < a.size() && time(a.get(upTo)) <= AT) {
            upTo++;
        }
        assertEquals(a.subList(0, upTo), b.subList(0, upTo), "the step logs up to t=" + AT + " ms");
        assertNotEquals(a.subList(upTo, a.size()), b.subList(upTo, b.size()), "the edited agent drives otherwise");
        assertTrue(String.join("\n", b.subList(upTo, b.size())).contains("@driveSlow"), "the edited plan is chosen");
        assertTrue(!String.join("\n", a).contains("@driveSlow"));

        String head = prefix(original, AT / 40);
        assertTrue(head.length() > 1000);
        assertEquals(head, prefix(r.eventLog(), AT / 40), "the event logs up to the instant, byte for byte");
        assertNotEquals(original, r.eventLog());
    }

    /** The page's reload of plans into a live run halted at an instant: the run goes on with the edited plans. */
    @Test
    @Timeout(180)
    void plansReloadedIntoAHaltedLiveRun(@TempDir Path dir) throws Exception {
        var quiet = new PrintStream(OutputStream.nullOutputStream());
        AgentSource original = agent("breaker.asl");
        var run = new LockstepRun(world(), null, EXPERIMENT, original, 1, quiet);
        var debugger = new Debugger();
        debugger.add("t=3s");
        String[] failed = {null};
        try (Inspector inspector = Inspector.startOnFreePort(); RunTap tap = RunTap.attach(run, inspector, dir, EXPERIMENT, "breaker.asl")) {
            tap.debugger(inspector, debugger);
            var edits = PageEdits.live(inspector, dir, tap.header(), EXPERIMENT, original, WhatIfTest::world,
                    run.mas().agent("robot"), debugger);
            assertThrows(IllegalStateException.class, () -> edits.reload(agent("breaker-edited.asl").text()), "not halted yet");
            Thread reloader = new Thread(() -> {
                try {
                    debugger.awaitHalt();
                    edits.reload(agent("breaker-edited.asl").text());
                    debugger.resume();
                } catch (Exception e) {
                    failed[0] = e.toString();
                    debugger.detach();
                }
            });
            reloader.start();
            run.runFor(6);
            reloader.join(10_000);
        }
        assertEquals(null, failed[0]);
        List<String> plans = StepArchive.open(dir, (t, x, z) -> {
        }).header().plans();
        assertTrue(plans.stream().anyMatch(p -> p.startsWith("@drive +!drive(N)")), "the plan library at the start, in the header: " + plans);
        List<String> steps = steps(dir);
        int at = 0;
        while (time(steps.get(at)) < AT) {
            at++;
        }
        assertTrue(!String.join("\n", steps.subList(0, at + 1)).contains("@driveSlow"), "the old plans up to the halt");
        assertTrue(String.join("\n", steps.subList(at + 1, steps.size())).contains("@driveSlow"), "the edited plan after it");
    }

    /** The event log's lines of steps 0..lastStep. */
    private static String prefix(String log, long lastStep) {
        var out = new StringBuilder();
        for (String line : log.split("\n", -1)) {
            String[] w = line.split(" ", 3);
            if (w.length >= 2 && w[0].equals("step") && Long.parseLong(w[1]) > lastStep) {
                break;
            }
            out.append(line).append('\n');
        }
        return out.toString();
    }

    private static long time(String stepLine) {
        return Long.parseLong(stepLine.replaceFirst("^\\{\"t\":(\\d+).*", "$1"));
    }

    /** The step lines (without the header). */
    private static List<String> steps(Path dir) throws Exception {
        try (var in = new GZIPInputStream(Files.newInputStream(dir.resolve(StepLog.FILE)))) {
            var lines = new ArrayList<>(List.of(new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")));
            lines.remove(0);
            return lines;
        }
    }
}
