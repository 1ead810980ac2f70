package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.cli.ServedReplay;
import jacabot.app.replay.Replay;
import jacabot.app.replay.RunTap;
import jacabot.app.replay.StepArchive;
import jacabot.app.replay.SyntheticRun;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * The mind inspector in a real browser (Debian's headless Chromium through Selenium): a lockstep
 * run of experiment 3 goes on in the background, paced to a few times real time, and the page
 * must follow it: beliefs and intentions on screen, the robot's pose changing as it moves, the
 * deliberation trace filling up, and the time slider going back to an earlier instant.
 * Skipped, saying why, where Chromium or chromedriver is missing.
 */
class InspectorBrowserTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    @Timeout(240)
    void pageFollowsTheRobotsMind(@TempDir Path dir) throws Exception {

        Experiment experiment = Experiment.parse("navigation").orElseThrow();
        var spec = WorldFileReader.read(ROOT.resolve(experiment.worldFile()));
        SimWorld world = SimWorld.of(spec);
        var source = AgentSource.packaged(experiment);
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        // the agent's console with its simulated times, as jacabot experiment writes it
        var consoleFile = ConsoleRecorder.open(dir, world::timeMs);
        var run = new LockstepRun(world, null, experiment, source, spec.seed(), consoleFile.tee(quiet)).stepLogs(false);
        AtomicBoolean stop = new AtomicBoolean();
        try (Inspector inspector = Inspector.startOnFreePort(); RunTap tap = RunTap.attach(run, inspector, null, experiment, "navigation.asl")) {
            inspector.title("experiment navigation (browser test)");
            inspector.console(ConsoleFile.of(dir));
            // paced to about 8x real time so the page sees the robot move; stopped at the end of the test
            run.onStep(d -> {
                if (stop.get()) {
                    throw new IllegalStateException("test over");
                }
                consoleFile.events(List.of());
                sleep(5);
            });
            Thread runner = new Thread(() -> {
                try {
                    run.runFor(300);
                } catch (Exception e) {
                    // the test stopped it
                }
            }, "lockstep-run");
            runner.setDaemon(true);
            runner.start();

            WebDriver browser = Browser.open();
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(40), Duration.ofMillis(100));
                wait.ignoring(StaleElementReferenceException.class);
                wait.until(b -> count(b, "#beliefs li.belief") > 0 && count(b, "#intentions .intention") > 0);
                String pose0 = Browser.text(browser, "robot-pose");
                String beliefs0 = Browser.text(browser, "beliefs");
                String intentions0 = Browser.text(browser, "intentions");
                double t0 = Double.parseDouble(Browser.text(browser, "time"));
                assertTrue(beliefs0.contains("source(percept)") || beliefs0.contains("source(self)"), beliefs0);
                assertTrue(count(browser, "#intentions mark.current") > 0, "the step about to run is marked");

                // live: the robot moves, its beliefs and intentions change
                wait.until(b -> !Browser.text(b, "robot-pose").equals(pose0));
                wait.until(b -> !Browser.text(b, "beliefs").equals(beliefs0));
                wait.until(b -> !Browser.text(b, "intentions").equals(intentions0));
                wait.until(b -> count(b, "#selections tbody tr") > 0);
                String selection = query(browser, "#selections tbody tr");
                assertTrue(selection.contains("{") && selection.contains("}"), "a unifier in " + selection);
                // the artifacts panel, live: the middleware's operations and the agent focusing on it
                wait.until(b -> Browser.text(b, "artifacts").contains("acquireData/0"));
                assertEquals("robot", ((JavascriptExecutor) browser).executeScript("return [...document.querySelectorAll("
                        + "'#artifacts tbody tr')].find(r => r.cells[0].textContent === 'middleware').cells[4].textContent"));
                // its operation log, from the page's first look on: the runner delivering readings, the agent's own operations
                wait.until(b -> {
                    String log = String.valueOf(((JavascriptExecutor) b).executeScript("return [...document.querySelectorAll("
                            + "'#artifacts tbody tr')].find(r => r.cells[0].textContent === 'middleware').cells[5].textContent"));
                    return log.contains(" s runner deliverStep/1") && log.matches("(?s).*\\d s robot \\w+/\\d.*");
                });
                // on a loaded machine the time line may trail the beliefs by a push or two
                wait.until(b -> Double.parseDouble(Browser.text(b, "time")) > t0);
                double t1 = Double.parseDouble(Browser.text(browser, "time"));
                assertTrue(t1 > t0, "time goes on: " + t0 + " then " + t1);
                // the console panel, live: what the agent printed at its start, with its simulated time
                wait.until(b -> query(b, "#console tbody").contains("[robot] focus achieved"));
                Browser.screenshot(browser, "inspector-live.png");

                // the time slider: back to the first kept frame, the page stops following
                wait.until(b -> ((Boolean) ((JavascriptExecutor) b).executeScript(
                        "const s = document.getElementById('slider'); return Number(s.max) > Number(s.min) + 5;")));
                ((JavascriptExecutor) browser).executeScript("const s = document.getElementById('slider');"
                        + " s.value = s.min; s.dispatchEvent(new Event('input'));");
                wait.until(b -> Browser.text(b, "live").startsWith("paused"));
                wait.until(b -> Double.parseDouble(Browser.text(b, "time")) < t1);
                double back = Double.parseDouble(Browser.text(browser, "time"));
                sleep(700);
                assertTrue(Double.parseDouble(Browser.text(browser, "time")) == back, "paused on the past frame");
                assertNotEquals(pose0, "");
                Browser.screenshot(browser, "inspector-history.png");
            } finally {
                browser.quit();
                stop.set(true);
                runner.join(10_000);
                consoleFile.close();
            }
        }
    }

    /**
     * A recorded 10-minute run served as {@code jacabot replay RUN --headless --inspector} serves it:
     * the slider reaches t = 0, and the canvas draws the robot where the step log puts it, at the
     * start and at 300 s; a click on a console line (shown around the instant, or found by its text
     * anywhere in the run) moves the page to that line's instant.
     */
    @Test
    @Timeout(240)
    void recordedTenMinuteRunFromItsStartWithTheRobotDrawnWhereTheLogPutsIt(@TempDir Path dir)
            throws Exception {
        SyntheticRun.write(dir, 600);
        // its console: a line every 3 s, and one failure late in the run
        var console = new StringBuilder();
        for (int i = 0; i < 200; i++) {
            console.append(String.format(Locale.ROOT, "t=%.3f [robot] tick %d%n", 3.0 * i, i));
            if (i == 137) {
                console.append("t=412.040 [robot] move failed\n");
            }
        }
        Files.writeString(dir.resolve(ConsoleFile.FILE), console);
        try (Inspector inspector = Inspector.startOnFreePort()) {
            StepArchive.show(inspector, dir); // as replay --headless --inspector does
            inspector.console(ConsoleFile.of(dir));
            WebDriver browser = Browser.open();
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(40), Duration.ofMillis(100));
                wait.until(b -> Browser.script(b, "return window.drawnRobots && window.drawnRobots.length") != null
                        && ((Number) Browser.script(b, "return Number(document.getElementById('slider').max)")).longValue() == 600_000);
                assertEquals(40L, ((Number) Browser.script(browser, "return Number(document.getElementById('slider').min)")).longValue(),
                        "the slider reaches the run's first step");
                for (long t : new long[] {40, 300_000}) {
                    robotDrawnAt(browser, wait, t, SyntheticRun.x(t, 600_000), SyntheticRun.z(t));
                }
                // the console panel: lines around the instant shown (300 s); a click on one goes to its instant
                wait.until(b -> Browser.script(b, "return document.querySelector('#console tr[data-t=\"261000\"]')") != null);
                Browser.script(browser, "document.querySelector('#console tr[data-t=\"261000\"]').click();");
                wait.until(b -> ((Number) Browser.script(b, "return window.shownTimeMs || -1")).longValue() == 261_000);
                assertEquals("261000", Browser.script(browser, "return document.getElementById('slider').value"));
                assertEquals("261.00", Browser.text(browser, "time"));
                wait.until(b -> "261000".equals(Browser.script(b, "const r = document.querySelector('#console tr.now'); return r && r.dataset.t")));
                // found anywhere in the run by its text, then clicked
                Browser.script(browser, "document.getElementById('console-find').value = 'failed'; document.getElementById('console-find-go').click();");
                wait.until(b -> Browser.script(b, "return document.querySelector('#console tr[data-t=\"412040\"]')") != null);
                assertEquals(1L, Browser.script(browser, "return document.querySelectorAll('#console tr').length"), "only the line found");
                Browser.script(browser, "document.querySelector('#console tr[data-t=\"412040\"]').click();");
                wait.until(b -> ((Number) Browser.script(b, "return window.shownTimeMs || -1")).longValue() == 412_040);
                assertEquals(SyntheticRun.x(412_040, 600_000), ((Number) Browser.script(browser, "return window.drawnRobots[0].x")).doubleValue(),
                        1e-9, "the world drawn at the line's instant");
                Browser.screenshot(browser, "inspector-replay.png");
            } finally {
                browser.quit();
            }
        }
    }

    /**
     * {@code jacabot replay RUN --headless --inspector}, the command itself, on a real recorded run:
     * the page it prints opens in the browser, whose slider spans the run from its first step and
     * whose canvas draws the robot where the step log puts it, at the start and at 6 s.
     */
    @Test
    @Timeout(180)
    void theReplayCommandServesARecordedRunToTheBrowser(@TempDir Path dir) throws Exception {
        Path runDir = dir.resolve("run");
        ServedReplay.record("navigation", "10s", 2, runDir);
        Replay recorded = Replay.open(runDir);
        try (ServedReplay served = ServedReplay.start(runDir)) {
            WebDriver browser = Browser.open();
            try {
                browser.get(served.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(40), Duration.ofMillis(100));
                long last = recorded.frames().get(recorded.frames().size() - 1).timeMs();
                wait.until(b -> Browser.script(b, "return window.drawnRobots && window.drawnRobots.length") != null
                        && ((Number) Browser.script(b, "return Number(document.getElementById('slider').max)")).longValue() == last);
                assertEquals(recorded.frames().get(0).timeMs(),
                        ((Number) Browser.script(browser, "return Number(document.getElementById('slider').min)")).longValue(),
                        "the slider reaches the run's first step");
                for (long at : new long[] {0, 6_000}) {
                    Replay.Frame f = recorded.frames().get(recorded.indexAt(Math.max(at, recorded.frames().get(0).timeMs())));
                    robotDrawnAt(browser, wait, f.timeMs(), f.body().x(), f.body().z());
                }
                Browser.screenshot(browser, "inspector-replay-command.png");
            } finally {
                browser.quit();
            }
        }
    }

    /**
     * Moves the slider to {@code t} (ms) and checks the robot is drawn at ({@code x}, {@code z}):
     * the page's drawn position, and the robot's colour on the canvas there (behind its heading line).
     */
    private static void robotDrawnAt(WebDriver browser, WebDriverWait wait, long t, double x, double z) {
        Browser.script(browser, "const s = document.getElementById('slider'); s.value = arguments[0];"
                + " s.dispatchEvent(new Event('input'));", t);
        wait.until(b -> ((Number) Browser.script(b, "return window.shownTimeMs ?? -1")).longValue() == t);
        assertEquals(x, ((Number) Browser.script(browser, "return window.drawnRobots[0].x")).doubleValue(), 1e-9, "x at " + t);
        assertEquals(z, ((Number) Browser.script(browser, "return window.drawnRobots[0].z")).doubleValue(), 1e-9, "z at " + t);
        String robot = (String) Browser.script(browser, "const v = window.inspectorView, r = window.drawnRobots[0];"
                + " const s = v.toScreen(r.x - 0.015, r.z - 0.015);"
                + " const d = document.getElementById('world').getContext('2d').getImageData(Math.round(s[0]), Math.round(s[1]), 1, 1).data;"
                + " return d[0] + ',' + d[1] + ',' + d[2];");
        String expected = (String) Browser.script(browser, "const c = (world.robots[0] || {}).color;"
                + " return c.red + ',' + c.green + ',' + c.blue;");
        assertEquals(expected, robot, "the robot's colour on the canvas at t=" + t);
    }

    private static String query(WebDriver b, String css) {
        Object t = ((JavascriptExecutor) b).executeScript(
                "const e = document.querySelector(arguments[0]); return e ? e.innerText : '';", css);
        return t == null ? "" : t.toString();
    }

    private static int count(WebDriver b, String css) {
        return ((Number) ((JavascriptExecutor) b).executeScript(
                "return document.querySelectorAll(arguments[0]).length;", css)).intValue();
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

}
