package jacabot.app.inspector;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Assumptions;
import org.openqa.selenium.JavascriptExecutor;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.TakesScreenshot;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;

/** The inspector's browser tests' Chromium: Debian's, through its chromedriver (Selenium Manager never downloads one). */
final class Browser {
    private Browser() {
    }

    private static Path find(String... candidates) {
        for (String c : candidates) {
            Path p = Path.of(c);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    /** {@return a headless Chromium}; skips the test, saying why, where Chromium or chromedriver is missing */
    static WebDriver open() {
        Path chromium = find("/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome");
        Path driverBinary = find("/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver");
        Assumptions.assumeTrue(chromium != null && driverBinary != null,
                "Chromium or chromedriver is missing (apt-get install -y chromium chromium-driver): "
                        + "the inspector's browser test did not run");
        var options = new ChromeOptions();
        options.setBinary(chromium.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu",
                "--window-size=1400,1000");
        var service = new ChromeDriverService.Builder().usingDriverExecutable(driverBinary.toFile()).build();
        return new ChromeDriver(service, options);
    }

    static Object script(WebDriver b, String js, Object... args) {
        return ((JavascriptExecutor) b).executeScript(js, args);
    }

    /** Reads an element's text in one script: the page re-renders while the test reads it. */
    static String text(WebDriver b, String id) {
        Object t = script(b, "const e = document.getElementById(arguments[0]); return e ? e.innerText : '';", id);
        return t == null ? "" : t.toString();
    }

    static void click(WebDriver b, String id) {
        script(b, "document.getElementById(arguments[0]).click();", id);
    }

    /** Keeps a screenshot in build/inspector-screenshots (and in -Djacabot.screenshots=DIR when asked, e.g. docs/images). */
    static void screenshot(WebDriver browser, String name) throws Exception {
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
}
