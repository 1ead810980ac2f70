package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.replay.RunTap;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;
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

    private static Path find(String... candidates) {
        for (String c : candidates) {
            Path p = Path.of(c);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    @Test
    @Timeout(240)
    void pageFollowsTheRobotsMind() throws Exception {
        Path chromium = find("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome");
        Path driverBinary = find("/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver");
        Assumptions.assumeTrue(chromium != null && driverBinary != null,
                "Chromium or chromedriver is missing (apt-get install -y chromium chromium-driver): "
                        + "the inspector's browser test did not run");

        Experiment experiment = Experiment.parse("navigation").orElseThrow();
        var spec = WorldFileReader.read(ROOT.resolve(experiment.worldFile()));
        SimWorld world = SimWorld.of(spec);
        var source = jacabot.app.run.AgentSource.packaged(experiment);
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        var run = new LockstepRun(world, null, experiment, source, spec.seed(), quiet).stepLogs(false);
        AtomicBoolean stop = new AtomicBoolean();
        try (Inspector inspector = Inspector.startOnFreePort(); RunTap tap = RunTap.attach(run, inspector, null, experiment, "navigation.asl")) {
            inspector.title("experiment navigation (browser test)");
            // paced to about 8x real time so the page sees the robot move; stopped at the end of the test
            run.onStep(d -> {
                if (stop.get()) {
                    throw new IllegalStateException("test over");
                }
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

            WebDriver browser = openBrowser(chromium, driverBinary);
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(40), Duration.ofMillis(100));
                wait.ignoring(StaleElementReferenceException.class);
                wait.until(b -> count(b, "#beliefs li.belief") > 0 && count(b, "#intentions .intention") > 0);
                String pose0 = text(browser, "robot-pose");
                String beliefs0 = text(browser, "beliefs");
                String intentions0 = text(browser, "intentions");
                double t0 = Double.parseDouble(text(browser, "time"));
                assertTrue(beliefs0.contains("source(percept)") || beliefs0.contains("source(self)"), beliefs0);
                assertTrue(count(browser, "#intentions mark.current") > 0, "the step about to run is marked");

                // live: the robot moves, its beliefs and intentions change
                wait.until(b -> !text(b, "robot-pose").equals(pose0));
                wait.until(b -> !text(b, "beliefs").equals(beliefs0));
                wait.until(b -> !text(b, "intentions").equals(intentions0));
                wait.until(b -> count(b, "#selections tbody tr") > 0);
                String selection = query(browser, "#selections tbody tr");
                assertTrue(selection.contains("{") && selection.contains("}"), "a unifier in " + selection);
                // on a loaded machine the time line may trail the beliefs by a push or two
                wait.until(b -> Double.parseDouble(text(b, "time")) > t0);
                double t1 = Double.parseDouble(text(browser, "time"));
                assertTrue(t1 > t0, "time goes on: " + t0 + " then " + t1);
                screenshot(browser, "inspector-live.png");

                // the time slider: back to the first kept frame, the page stops following
                wait.until(b -> ((Boolean) ((JavascriptExecutor) b).executeScript(
                        "const s = document.getElementById('slider'); return Number(s.max) > Number(s.min) + 5;")));
                ((JavascriptExecutor) browser).executeScript("const s = document.getElementById('slider');"
                        + " s.value = s.min; s.dispatchEvent(new Event('input'));");
                wait.until(b -> text(b, "live").startsWith("paused"));
                wait.until(b -> Double.parseDouble(text(b, "time")) < t1);
                double back = Double.parseDouble(text(browser, "time"));
                sleep(700);
                assertTrue(Double.parseDouble(text(browser, "time")) == back, "paused on the past frame");
                assertNotEquals(pose0, "");
                screenshot(browser, "inspector-history.png");
            } finally {
                browser.quit();
                stop.set(true);
                runner.join(10_000);
            }
        }
    }

    /**
     * A recorded 10-minute run served as {@code jacabot replay RUN --headless --inspector} serves it:
     * the slider reaches t = 0, and the canvas draws the robot where the step log puts it, at the
     * start and at 300 s.
     */
    @Test
    @Timeout(240)
    void recordedTenMinuteRunFromItsStartWithTheRobotDrawnWhereTheLogPutsIt(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        Path chromium = find("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome");
        Path driverBinary = find("/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver");
        Assumptions.assumeTrue(chromium != null && driverBinary != null,
                "Chromium or chromedriver is missing (apt-get install -y chromium chromium-driver): "
                        + "the inspector's browser test did not run");
        jacabot.app.replay.SyntheticRun.write(dir, 600);
        try (Inspector inspector = Inspector.startOnFreePort()) {
            jacabot.app.replay.StepArchive.show(inspector, dir);
            WebDriver browser = openBrowser(chromium, driverBinary);
            try {
                browser.get(inspector.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(40), Duration.ofMillis(100));
                wait.until(b -> script(b, "return window.drawnRobots && window.drawnRobots.length") != null
                        && ((Number) script(b, "return Number(document.getElementById('slider').max)")).longValue() == 600_000);
                assertEquals(40L, ((Number) script(browser, "return Number(document.getElementById('slider').min)")).longValue(),
                        "the slider reaches the run's first step");
                for (long t : new long[] {40, 300_000}) {
                    script(browser, "const s = document.getElementById('slider'); s.value = arguments[0];"
                            + " s.dispatchEvent(new Event('input'));", t);
                    wait.until(b -> ((Number) script(b, "return window.shownTimeMs || -1")).longValue() == t);
                    double x = ((Number) script(browser, "return window.drawnRobots[0].x")).doubleValue();
                    double z = ((Number) script(browser, "return window.drawnRobots[0].z")).doubleValue();
                    assertEquals(jacabot.app.replay.SyntheticRun.x(t, 600_000), x, 1e-9, "x at " + t);
                    assertEquals(jacabot.app.replay.SyntheticRun.z(t), z, 1e-9, "z at " + t);
                    // the canvas has the robot's colour there (behind its heading line), and the floor's far from it
                    String robot = (String) script(browser, "const v = window.inspectorView, r = window.drawnRobots[0];"
                            + " const s = v.toScreen(r.x - 0.015, r.z - 0.015);"
                            + " const d = document.getElementById('world').getContext('2d').getImageData(Math.round(s[0]), Math.round(s[1]), 1, 1).data;"
                            + " return d[0] + ',' + d[1] + ',' + d[2];");
                    String expected = (String) script(browser, "const c = (world.robots[0] || {}).color;"
                            + " return c.red + ',' + c.green + ',' + c.blue;");
                    assertEquals(expected, robot, "the robot's colour on the canvas at t=" + t);
                }
                screenshot(browser, "inspector-replay.png");
            } finally {
                browser.quit();
            }
        }
    }

    private static Object script(WebDriver b, String js, Object... args) {
        return ((JavascriptExecutor) b).executeScript(js, args);
    }

    private static WebDriver openBrowser(Path chromium, Path driverBinary) {
        var options = new ChromeOptions();
        options.setBinary(chromium.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                "--window-size=1400,1000");
        // the driver Debian installed: Selenium Manager (a download) never runs
        var service = new ChromeDriverService.Builder().usingDriverExecutable(driverBinary.toFile()).build();
        return new ChromeDriver(service, options);
    }

    /** Reads an element's text in one script: the page re-renders while the test reads it. */
    private static String text(WebDriver b, String id) {
        Object t = ((JavascriptExecutor) b).executeScript(
                "const e = document.getElementById(arguments[0]); return e ? e.innerText : '';", id);
        return t == null ? "" : t.toString();
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

    /** Keeps a screenshot in build/inspector-screenshots (and in -Djacabot.screenshots=DIR when asked, e.g. docs/). */
    private static void screenshot(WebDriver browser, String name) throws Exception {
        byte[] png = ((TakesScreenshot) browser).getScreenshotAs(OutputType.BYTES);
        Path dir = Path.of(System.getProperty("jacabot.projectDir", "."), "build", "inspector-screenshots");
        Files.createDirectories(dir);
        Files.write(dir.resolve(name), png);
        String extra = System.getProperty("jacabot.screenshots");
        if (extra != null) {
            Files.createDirectories(Path.of(extra));
            Files.write(Path.of(extra, name), png);
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

}
