package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.remote.WorkspaceSecret;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;

/**
 * The projects of examples/jaca — our own agents and artifacts for the scenarios of CArtAgO 3.1's
 * JaCa examples — run as {@code jacabot run} runs them (sources compiled, free-running agents),
 * and print what CArtAgO's description of each scenario says.
 */
class JacaExamplesTest {
    private static Path folder(String folder) {
        return Path.of(System.getProperty("jacabot.rootDir", ".."), "examples", "jaca", folder);
    }

    private static ProjectRun run(String folder) throws Exception {
        Path mas2j;
        try (var files = Files.list(folder(folder))) {
            mas2j = files.filter(p -> p.toString().endsWith(".mas2j")).findFirst().orElseThrow();
        }
        return run(folder, mas2j);
    }

    private static ProjectRun run(String folder, Path mas2j) throws Exception {
        ProjectRun run = ProjectRun.run(mas2j, 0, 90_000);
        assertTrue(run.stopped, folder + " did not end with .stopMAS:\n" + run.output);
        return run;
    }

    private static List<String> of(ProjectRun run, String agentPrefix) {
        return run.lines().stream().filter(l -> l.startsWith("[" + agentPrefix)).toList();
    }

    @Test
    void hello() throws Exception {
        assertEquals("[greeter] Hello, world!\n", run("00-hello").output);
    }

    @Test
    void anObserverSeesEveryChangeAndSignal() throws Exception {
        List<String> lines = run("01-observe").lines();
        // each value once; not necessarily in order: each +count(N) starts an intention of its own,
        // and their println operations run on two carriers at once, the console's lock taken by either
        assertEquals(List.of("[watcher] observed count 0", "[watcher] observed count 1", "[watcher] observed count 2"),
                lines.stream().filter(l -> l.contains("observed")).sorted().toList());
        assertEquals(2, lines.stream().filter(l -> l.equals("[watcher] perceived a tick")).count(), lines.toString());
        assertEquals(5, lines.size(), lines.toString());
    }

    @Test
    void aFailedOperationGivesItsReasonToTheFailurePlan() throws Exception {
        assertEquals(List.of("[user] the cap is reached", "[user] last value is 40"), run("02-failure").lines());
        assertEquals(List.of("[r0] attempt refused", "[tester] failure: refused on purpose reason_one 42"),
                run("02a-failure-reason").lines());
    }

    @Test
    void outputParameters() throws Exception {
        assertEquals(List.of("[calc_user] 4 + 5 = 9", "[calc_user] 0.5 + 1.5 = 2, 0.5 - 1.5 = -1"),
                run("03-output-params").lines());
    }

    @Test
    void producersAndConsumersPassEveryItemOnce() throws Exception {
        List<String> lines = run("04-producers-consumers").lines();
        Set<String> items = new HashSet<>();
        Pattern consumed = Pattern.compile("\\[(consumer[123])\\] \\1 consumed (item\\(producer[12],\\d+\\))");
        for (String l : lines) {
            Matcher m = consumed.matcher(l);
            assertTrue(m.matches(), l);
            assertTrue(items.add(m.group(2)), "consumed twice: " + l);
        }
        assertEquals(20, items.size(), lines.toString());
    }

    @Test
    void aComplexOperationWaitsForOthersBetweenItsSteps() throws Exception {
        ProjectRun run = run("05-complex-op");
        List<String> starter = of(run, "starter");
        assertEquals("[starter] first step done, contributions so far: 0", starter.get(0), run.output);
        // the second step's signal starts an intention of its own; "run completed" is the next step of
        // the one whose operation ended: two intentions, either may print first (as in Jason)
        assertEquals(Set.of("[starter] second step done, contributions: 12", "[starter] run completed"),
                Set.copyOf(starter.subList(1, starter.size())), run.output);
        assertEquals(3, starter.size(), run.output);
        assertEquals(4, of(run, "helper").size(), run.output);
    }

    private static void everyPhilosopherEatsThreeTimes(ProjectRun run) {
        for (int i = 1; i <= 5; i++) {
            String me = "philosopher" + i;
            List<String> meals = of(run, me + "]");
            String forks = "[" + me + "] " + me + " eats with forks " + (i - 1) + " and " + (i % 5);
            assertEquals(List.of(forks, forks, forks), meals, run.output);
            assertTrue(run.lines().contains("[host] " + me + " is full"), run.output);
        }
        assertEquals("[host] all philosophers ate", run.lines().get(run.lines().size() - 1));
    }

    @Test
    void philosophersThroughTheBlackboard() throws Exception {
        everyPhilosopherEatsThreeTimes(run("05a-philosophers-blackboard"));
    }

    @Test
    void philosophersWithForkArtifacts() throws Exception {
        everyPhilosopherEatsThreeTimes(run("05b-philosophers-artifacts"));
    }

    @Test
    void aClockTicksUntilStopped() throws Exception {
        List<String> lines = run("06-clock").lines();
        assertEquals(12, lines.size(), lines.toString());
        assertEquals("[clock_user] clock starting", lines.get(0));
        for (int i = 1; i <= 10; i++) {
            assertEquals("[clock_user] tick " + i, lines.get(i));
        }
        assertEquals("[clock_user] clock stopped", lines.get(11));
    }

    @Test
    void linkedArtifacts() throws Exception {
        assertEquals(List.of("[link_tester] linked", "[dispatcher] read back 10", "[link_tester] total through the port: 10",
                "[link_tester] total of its own accumulator: 101",
                "[link_tester] an agent cannot call a link operation: unknown_operation(\"add\",1)"),
                run("08-linking").lines());
    }

    @Test
    void contractNet() throws Exception {
        ProjectRun run = run("12-contract-net");
        List<String> announcer = of(run, "announcer");
        assertEquals("[announcer] announced t0 on auction_1", announcer.get(0), run.output);
        long made = run.lines().stream().filter(l -> l.matches("\\[bidder\\d\\] offer \\d made")).count();
        long late = run.lines().stream().filter(l -> l.matches("\\[bidder\\d\\] too late for an offer")).count();
        assertEquals(5, made + late, run.output);
        assertEquals("[announcer] got " + made + " offers", announcer.get(1));
        if (made == 0) {
            // the deadline is wall time: on a machine loaded many times over, every bidder may be late
            assertEquals(5, late, run.output);
            assertEquals("[announcer] all bidders done", announcer.get(announcer.size() - 1));
            return;
        }
        assertTrue(announcer.get(2).matches("\\[announcer\\] awarded to offer_of_bidder\\d"), run.output);
        assertEquals(1, run.lines().stream().filter(l -> l.endsWith("] I won")).count(), run.output);
        assertEquals(made - 1, run.lines().stream().filter(l -> l.endsWith("] I lost")).count(), run.output);
        assertEquals("[announcer] all bidders done", announcer.get(announcer.size() - 1));
    }

    @Test
    void aThreadOutsideTheAgentsUpdatesAnArtifactThroughAnExternalSession() throws Exception {
        List<String> lines = run("ext-thread").lines();
        assertEquals(1, lines.size(), lines.toString());
        // 13 is reached only through the meter's own thread; then bump adds 100
        assertTrue(lines.get(0).matches("\\[reader\\] bumped to 11[3-9]|\\[reader\\] bumped to 1[2-9]\\d"), lines.get(0));
    }

    @Test
    void commandsOutputAsOutputParameterAndAsSignals() throws Exception {
        assertEquals(List.of("[shell_user] first line: hello from sh", "[shell_user] line 1: 1", "[shell_user] line 2: 2",
                "[shell_user] line 3: 3", "[shell_user] done", "[shell_user] a failing command: exit code 3"),
                run("07b-shell").lines());
    }

    private static final String NO_DISPLAY =
            "[gui_user] init of demo.NumberWindow failed: no display for its window (DISPLAY unset, or java.awt.headless)";

    /**
     * Without a display (CI) the window cannot open and the agent says so in one line; with one,
     * the test works the window through the system's own events (java.awt.Robot): ok, a number
     * typed with ENTER, ok again, a drag, then closing the window, which stops the agent.
     */
    @Test
    void aSwingWindowAsAnArtifact() throws Exception {
        if (GraphicsEnvironment.isHeadless()) {
            assertEquals(List.of(NO_DISPLAY), run("07a-gui").lines());
            return;
        }
        var done = new CompletableFuture<ProjectRun>();
        new Thread(() -> {
            try {
                done.complete(run("07a-gui"));
            } catch (Throwable t) {
                done.completeExceptionally(t);
            }
        }, "07a-gui").start();
        JFrame frame = SwingDriver.frame("jacabot: 07a GUI", done);
        var number = SwingDriver.find(frame, JTextField.class, "number");
        var ok = SwingDriver.find(frame, JButton.class, "ok");
        var pad = SwingDriver.find(frame, JPanel.class, "pad");
        SwingDriver driver = new SwingDriver();
        driver.click(ok);
        driver.waitForText(number, "1");          // the agent answered ok with setValue(0 + 1)
        driver.click(number);
        driver.type(number, "41");
        driver.click(ok);
        driver.waitForText(number, "42");         // ENTER made value 41, then ok added one
        driver.drag(pad);
        SwingUtilities.invokeAndWait(() -> frame.dispatchEvent(
                new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        ProjectRun run = done.get(60, TimeUnit.SECONDS);
        List<String> lines = run.lines();
        List<String> values = lines.stream().filter(l -> !l.contains("mouse dragged")).toList();
        // the first value comes with the focus, a percept: the plan's next println may come first
        assertEquals(Set.of("[gui_user] value is now 0",
                "[gui_user] type a number and ENTER, press ok to add one, drag the mouse; close the window to stop"),
                Set.copyOf(values.subList(0, 2)), run.output);
        assertEquals(List.of("[gui_user] value is now 1", "[gui_user] value is now 41", "[gui_user] value is now 42",
                "[gui_user] window closed"), values.subList(2, values.size()), run.output);
        assertTrue(lines.stream().anyMatch(l -> l.matches("\\[gui_user\\] mouse dragged to \\d+,\\d+")), run.output);
        assertEquals("[gui_user] window closed", lines.get(lines.size() - 1), run.output);
    }

    @Test
    void socketsWrappedInArtifacts() throws Exception {
        assertEquals(List.of("[receiver] received hello1", "[receiver] received hello2", "[receiver] received hello3"),
                run("07-messages").lines());
    }

    @Test
    void javaObjectsThroughTheCartagoInternalActions() throws Exception {
        assertEquals(List.of("[binder] total: 9", "[binder] max: 9", "[binder] the clock runs",
                "[binder] class: class demo.Tally", "[binder] sorted: [1,2,3]",
                "[binder] ia_failed: cartago.invoke_obj: demo.Tally.reset(-1) threw java.lang.IllegalArgumentException: "
                        + "a tally never goes below zero",
                "[binder] ia_failed: cartago.invoke_obj: no public method demo.Tally.multiply for (2)"),
                run("09-java-binding").lines());
    }

    @Test
    void severalWorkspacesEachWithItsOwnBlackboard() throws Exception {
        assertEquals(List.of("[visitor] starting in main", "[visitor] cannot join: unknown_workspace(\"attic\")",
                "[visitor] now in kitchen", "[visitor] now in garden", "[visitor] not here: unknown_artifact(\"pot\")",
                "[visitor] back in kitchen", "[visitor] the note here: left in the kitchen",
                "[visitor] the pot was stirred 1 time(s)", "[visitor] after quitting: garden",
                "[visitor] and finally in main again", "[visitor] joined: [\"main\"]"),
                run("10-workspaces").lines());
    }

    @Test
    void anAgentOfAnotherNodeWorksInThisNodesWorkspace() throws Exception {
        int port;
        try (var probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = probe.getLocalPort();
        }
        Path secret = Files.createTempDirectory("jacabot-secret").resolve("workspace-secret");
        System.setProperty("jacabot.cartago.port", String.valueOf(port));
        System.setProperty(WorkspaceSecret.FILE_PROPERTY, secret.toString());
        try {
            var node = new CompletableFuture<ProjectRun>();
            var nodeThread = new Thread(() -> {
                try {
                    node.complete(run("11-remote", folder("11-remote").resolve("node.mas2j")));
                } catch (Throwable t) {
                    node.completeExceptionally(t);
                }
            });
            nodeThread.start();
            long deadline = System.currentTimeMillis() + 60_000;
            while (true) {   // until the node listens
                try (var probe = new Socket(InetAddress.getLoopbackAddress(), port)) {
                    break;
                } catch (IOException notYet) {
                    assertTrue(System.currentTimeMillis() < deadline && !node.isDone(), "the node never listened");
                    Thread.sleep(50);
                }
            }
            ProjectRun visitor = run("11-remote", folder("11-remote").resolve("visitor.mas2j"));
            assertEquals(List.of("[voyager] no attic there: join_failed(\"attic\",\"localhost\")",
                    "[voyager] joined main remotely", "[voyager] count is 2", "[voyager] back in main",
                    "[voyager] beliefs about the tally left: 0"), visitor.lines());
            // the node's console prints what the visitor printed while its current workspace was the node's:
            // before the tally it made there counted to 2; the keeper's first line is its own, it may come
            // after the visitor's (two processes: the test waits for the node's port, not for its agent)
            List<String> lines = node.get(90, TimeUnit.SECONDS).lines();
            String hello = "[voyager] hello from another process";
            assertEquals(List.of("[keeper] keeping main (local)", "[keeper] the visitor counted to 2",
                    "[keeper] the visitor left"), lines.stream().filter(l -> !l.equals(hello)).toList(), lines.toString());
            assertEquals(1, lines.stream().filter(hello::equals).count(), lines.toString());
            assertTrue(lines.indexOf(hello) < lines.indexOf("[keeper] the visitor counted to 2"), lines.toString());
        } finally {
            System.clearProperty("jacabot.cartago.port");
            System.clearProperty(WorkspaceSecret.FILE_PROPERTY);
        }
    }
}
