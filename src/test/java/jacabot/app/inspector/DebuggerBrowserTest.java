package jacabot.app.inspector;

import static jacabot.app.inspector.Browser.click;
import static jacabot.app.inspector.Browser.script;
import static jacabot.app.inspector.Browser.text;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.replay.PageEdits;
import jacabot.app.replay.Replay;
import jacabot.app.replay.RunTap;
import jacabot.app.replay.StepArchive;
import jacabot.app.replay.StepLog;
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
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The debugger from the inspector's page, in Chromium: a breakpoint on a plan label typed into the
 * page halts the run at the step the step log of an unpaused run predicts, "cycle" goes one
 * reasoning cycle on, "continue" lets it finish with the same event log, byte for byte, as the
 * run never paused; and a what-if started from the page on a recorded run is that run up to its
 * instant (the page says where it first differs) and shows as another agent. The agent is the
 * debugger tests' own ({@code breaker.asl}), in experiment 1's world.
 */
class DebuggerBrowserTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final Experiment EXPERIMENT = Experiment.parse("obstacle-avoidance").orElseThrow();
    static final PrintStream QUIET = new PrintStream(OutputStream.nullOutputStream());

    private static String resource(String name) throws Exception {
        try (InputStream in = DebuggerBrowserTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private static SimWorld world() throws Exception {
        return SimWorld.of(WorldFileReader.read(ROOT.resolve(EXPERIMENT.worldFile())));
    }

    private static LockstepRun breaker(Path agentFile) throws Exception {
        return new LockstepRun(world(), null, EXPERIMENT, AgentSource.file(agentFile), 1, QUIET);
    }

    @Test
    @Timeout(300)
    void breakpointCycleAndContinueFromThePage(@TempDir Path plain, @TempDir Path paused) throws Exception {
        Path agent = Files.writeString(plain.resolve("breaker.asl"), resource("breaker.asl"));
        String expected;
        var first = breaker(agent);
        try (RunTap tap = RunTap.attach(first, null, plain, EXPERIMENT, agent.toString())) {
            expected = first.runFor(6).eventLog();
        }
        long predicted = -1;
        for (Replay.Frame f : Replay.open(plain).frames()) {
            if (predicted < 0 && f.mind().selections().stream().anyMatch(s -> s.plan().startsWith("@drive"))) {
                predicted = f.timeMs();
            }
        }
        assertTrue(predicted > 0, "the plain run selects @drive");

        var run = breaker(agent);
        var debugger = new Debugger();
        debugger.pause(); // halts after its first step: the page sets the breakpoint
        String[] log = new String[1];
        try (Inspector inspector = Inspector.startOnFreePort();
                RunTap tap = RunTap.attach(run, inspector, paused, EXPERIMENT, agent.toString())) {
            tap.debugger(inspector, debugger);
            Thread runner = new Thread(() -> {
                try {
                    log[0] = run.runFor(6).eventLog();
                } catch (Exception e) {
                    log[0] = "failed: " + e;
                }
            }, "paused-run");
            runner.setDaemon(true);
            runner.start();
            WebDriver browser = Browser.open();
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(60), Duration.ofMillis(100));
                wait.withMessage(() -> "the run: " + (debugger.halted() == null ? "running" : debugger.halted().reason())
                        + "; the page: " + script(browser, "return JSON.stringify(window.debugState || null).slice(0, 300)"));
                wait.until(b -> text(b, "halted").contains("paused"));
                script(browser, "document.getElementById('break').value = 'label:drive';");
                click(browser, "add-break");
                wait.until(b -> text(b, "breakpoints").contains("label:drive"));
                click(browser, "continue");
                wait.until(b -> text(b, "halted").contains("@drive"));
                assertEquals(predicted, halted(browser).get("timeMs"), "halted at the step the step log predicts");
                wait.until(b -> text(b, "time").equals(String.format("%.2f", (double) debugger.halted().timeMs() / 1000)));
                Browser.screenshot(browser, "inspector-breakpoint.png");

                // one reasoning cycle: the page shows the mind one cycle on
                long cycle = debugger.halted().mind().cycle();
                click(browser, "cycle");
                wait.until(b -> text(b, "halted").contains("one reasoning cycle"));
                assertEquals(cycle + 1, debugger.halted().mind().cycle());
                wait.until(b -> text(b, "cycle").equals(String.valueOf(cycle + 1)));
                // the command's answer, read before the halt, may reach the page after the halt's push
                // (under load): an older state never replaces the one shown
                script(browser, "const d = window.debugState; showDebug(Object.assign({}, d, {version: d.version - 1, halted: null}));");
                assertTrue(text(browser, "halted").contains("one reasoning cycle"), "the halt stays shown");

                // the breakpoint deleted from the page, the run continued to its end
                script(browser, "document.querySelector('#breakpoints a').click();");
                wait.until(b -> !text(b, "breakpoints").contains("label:drive"));
                click(browser, "continue");
                runner.join(120_000);
            } finally {
                browser.quit();
            }
        }
        assertEquals(expected, log[0], "the event log of the run paused and stepped from the page");
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> halted(WebDriver b) {
        Map<String, Object> h = (Map<String, Object>) script(b, "return window.debugState.halted;");
        return Map.of("timeMs", ((Number) h.get("timeMs")).longValue(), "reason", h.get("reason"));
    }

    @Test
    @Timeout(300)
    void whatIfFromThePageIsTheRunUpToItsInstant(@TempDir Path recorded) throws Exception {
        Path agent = Files.writeString(recorded.resolve("breaker.asl"), resource("breaker.asl"));
        Path dir = recorded.resolve("run");
        var run = breaker(agent);
        try (RunTap tap = RunTap.attach(run, null, dir, EXPERIMENT, agent.toString())) {
            run.runFor(6);
        }
        try (Inspector inspector = Inspector.startOnFreePort()) {
            StepArchive archive = StepArchive.show(inspector, dir);
            inspector.edits(PageEdits.recorded(inspector, dir, archive.header(), DebuggerBrowserTest::world));
            WebDriver browser = Browser.open();
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(120), Duration.ofMillis(200));
                wait.until(b -> ((String) script(b, "return document.getElementById('program').value")).contains("@drive"));

                wait.until(b -> text(b, "plans").contains("@drive +!drive(N)")); // the plan library of a recorded run

                // the time views of the recorded run
                click(browser, "timeline-load");
                wait.until(b -> ((Number) script(b, "return (window.timelineSpans || []).length")).intValue() > 0);
                assertTrue((Boolean) script(browser, "return window.timelineSpans.some(s => s.plan.startsWith('@drive'))"),
                        "the timeline has the @drive plan's bars");
                script(browser, "document.getElementById('belief-name').value = 'connected';");
                click(browser, "belief-load");
                wait.until(b -> text(b, "belief-changes").contains("connected(true)"));
                wait.until(b -> text(b, "artifacts").contains("middleware"));
                long sensors = ((Number) script(browser, "return world.robots[0].rays.length")).longValue();
                assertTrue(sensors > 0);
                assertEquals(sensors, ((Number) script(browser, "return (window.drawnRays || []).length")).longValue(),
                        "every distance sensor's ray is drawn");
                assertTrue((Boolean) script(browser, "return window.drawnRays.every(r => r.value != null)"),
                        "each with its reading");
                // (the plan library names the test's temporary folder: out of the picture, which goes to the docs)
                script(browser, "document.getElementById('plans').parentElement.style.display = 'none';"
                        + " document.getElementById('timeline').scrollIntoView();");
                Browser.screenshot(browser, "inspector-time-views.png");
                script(browser, "document.getElementById('plans').parentElement.style.display = '';"
                        + " window.scrollTo(0, 0);");

                // a what-if from 3 s with the edited agent
                script(browser, "document.getElementById('program').value = arguments[0];"
                        + " document.getElementById('whatif-t').value = '3';"
                        + " document.getElementById('whatif-seconds').value = '6';", resource("breaker-edited.asl"));
                click(browser, "whatif-run");
                wait.until(b -> text(b, "whatifs").contains("done") || text(b, "whatifs").contains("failed"));
                @SuppressWarnings("unchecked")
                var job = (Map<String, Object>) script(browser, "return window.debugState.whatIfs[0];");
                assertEquals("done", job.get("state"), String.valueOf(job));
                assertEquals(3000L, ((Number) job.get("swappedAtMs")).longValue());
                long differs = ((Number) job.get("divergesAtMs")).longValue();
                assertTrue(differs > 3000, "the what-if is the recorded run up to its instant: it differs from " + differs);
                List<String> original = steps(dir), whatIf = steps(Path.of((String) job.get("folder")));
                int upTo = 0;
                while (upTo < original.size() && original.get(upTo).startsWith("{\"t\":")
                        && Long.parseLong(original.get(upTo).replaceFirst("^\\{\"t\":(\\d+).*", "$1")) <= 3000) {
                    upTo++;
                }
                assertEquals(original.subList(0, upTo), whatIf.subList(0, upTo), "byte for byte up to 3 s");

                // shown as another agent, its path beside the run's
                script(browser, "document.querySelector('#whatifs a.show').click();");
                wait.until(b -> text(b, "agents").contains("what-if 1"));
                wait.until(b -> ((String) script(b, "const o = document.querySelector('#agents button.on'); return o ? o.textContent : ''"))
                        .startsWith("what-if 1"));
                wait.until(b -> (Boolean) script(b, "return Object.keys(others).includes('robot') && others.robot.length > 1"));
                // the other agent's robot drawn at the same instant (a team's run draws every robot)
                wait.until(b -> (Boolean) script(b, "return window.drawnRobots.length === 2 && window.drawnRobots[1].name === 'robot'"));
                Browser.screenshot(browser, "inspector-what-if.png");
            } finally {
                browser.quit();
            }
        }
    }

    /** The step lines of a run's step log (without the header). */
    private static List<String> steps(Path dir) throws Exception {
        try (var in = new GZIPInputStream(Files.newInputStream(dir.resolve(StepLog.FILE)))) {
            var lines = new ArrayList<>(List.of(new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")));
            lines.remove(0);
            return lines;
        }
    }
}
