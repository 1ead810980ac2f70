package jacabot.app.inspector;

import static jacabot.app.inspector.Browser.click;
import static jacabot.app.inspector.Browser.script;
import static jacabot.app.inspector.Browser.text;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.app.cli.ServedReplay;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * A plan edited on the inspector's page and applied to a live real-time run, in Chromium: the
 * launcher's own {@code experiment --real-time --headless --inspector} (a server's run, no viewer)
 * with an agent that says which plan it runs. A what-if is refused there (it needs a lockstep
 * run's step log); a program that does not parse is refused with its location and changes
 * nothing; the edited program is applied at the agent's next reasoning cycle, the page says when,
 * its plan library shows the new body and the console the new plan's lines, from that instant on.
 */
class LiveEditBrowserTest {
    private static final String TICK = "// says which plan it runs, every 0.3 s of simulated time\n"
            + "!tick.\n"
            + "@tick +!tick <- .print(\"tick from the first plan\"); .wait(300); !tick.\n";
    private static final Pattern APPLIED = Pattern.compile("applied to the running agent at t = (\\d+\\.\\d\\d) s");

    @Test
    @Timeout(240)
    void aPlanEditedOnThePageIsTheRunningAgentsNextChoice(@TempDir Path dir) throws Exception {
        Path agent = Files.writeString(dir.resolve("tick.asl"), TICK);
        Path out = dir.resolve("run");
        double appliedAt;
        try (ServedReplay run = ServedReplay.experiment("obstacle-avoidance", "--real-time", "--headless", "--inspector",
                "--duration", "180s", "--agent", agent.toString(), "--out", out.toString(), "--inspector-port", "0")) {
            WebDriver browser = Browser.open();
            try {
                browser.get(run.address().toString());
                var wait = new WebDriverWait(browser, Duration.ofSeconds(60), Duration.ofMillis(100));
                wait.withMessage(() -> "the page: " + text(browser, "whatif-status") + "; the run: " + run.output());
                wait.until(b -> ((String) script(b, "return document.getElementById('program').value")).contains("@tick"));
                wait.until(b -> text(b, "reload").equals("apply these plans to the running agent"));
                wait.until(b -> text(b, "console").contains("tick from the first plan"));

                // a real-time run cannot be run again step for step: its what-if says so
                click(browser, "whatif-run");
                wait.until(b -> text(b, "whatif-status").contains("needs a lockstep run's step log"));

                // a program that does not parse: its place, and nothing applied
                script(browser, "document.getElementById('program').value = arguments[0];",
                        TICK.replace("first plan\");", "edited plan\")"));
                click(browser, "reload");
                wait.until(b -> text(b, "whatif-status").startsWith("not applied"));
                assertTrue(text(browser, "whatif-status").matches("(?s)not applied: .*tick\\.asl:3:\\d+.*"),
                        text(browser, "whatif-status"));
                assertTrue(text(browser, "plans").contains("tick from the first plan"), text(browser, "plans"));

                // the edit applied: when, the new body in the plan library, the new plan's lines in the console
                script(browser, "document.getElementById('program').value = arguments[0];",
                        TICK.replace("first plan", "edited plan"));
                click(browser, "reload");
                wait.until(b -> text(b, "whatif-status").startsWith("applied"));
                Matcher m = APPLIED.matcher(text(browser, "whatif-status"));
                assertTrue(m.find(), text(browser, "whatif-status"));
                appliedAt = Double.parseDouble(m.group(1));
                wait.until(b -> text(b, "plans").contains("tick from the edited plan"));
                assertTrue(!text(browser, "plans").contains("tick from the first plan"), text(browser, "plans"));
                wait.until(b -> text(b, "console").contains("tick from the edited plan"));
                script(browser, "document.getElementById('whatif-section').scrollIntoView();");
                Browser.screenshot(browser, "inspector-live-edit.png");
            } finally {
                browser.quit();
            }
        }
        // the run's console file: the swap marked at the instant the page was told, the edited plan's lines after it
        List<String> console = Files.readAllLines(out.resolve(ConsoleFile.FILE));
        int swap = -1;
        for (int i = 0; i < console.size(); i++) {
            if (console.get(i).endsWith("reload: the plans edited on the inspector's page from here on")) {
                swap = i;
            }
        }
        assertTrue(swap >= 0, String.join("\n", console));
        double marked = Double.parseDouble(console.get(swap).substring(2, console.get(swap).indexOf(' ')));
        assertEquals(appliedAt, marked, 0.0051, "the instant the page was told: " + console.get(swap));
        List<String> before = console.subList(0, swap), after = console.subList(swap, console.size());
        assertTrue(before.stream().noneMatch(l -> l.contains("edited plan")), "no edited line before the swap");
        assertTrue(after.stream().filter(l -> l.contains("tick from the first plan")).count() <= 1,
                "at most the step the running intention had already chosen: " + after);
        assertTrue(after.stream().anyMatch(l -> l.contains("tick from the edited plan")), String.join("\n", after));
    }
}
