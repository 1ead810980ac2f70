package jacabot.agent.testing;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.DefaultEnvironment;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.MasLauncher;
import jacabot.agent.runtime.SimulatedTime;
import jacabot.agent.semantics.Clock;
import jacabot.agent.testing.AslTestCase.Status;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Runs AgentSpeak unit tests as Jason users write them: tester agents with {@code @[test]} plans
 * and the assert goals of Jason's test library ({@code !assert_equals(2, N)}), and reports each
 * test. Two kinds of unit:
 * <ul>
 * <li>a test file ({@code .asl} including {@code tester_agent.asl}, with a plan labelled {@code [test]}):
 *     run with the library's {@code test_manager}, as agent named after the file, its environment
 *     actions answered by its {@code mock_operation} beliefs ({@link MockingArch});</li>
 * <li>a test project ({@code .mas2j} with a {@code test_manager} agent): run as {@code jacabot run} runs it.</li>
 * </ul>
 * A unit runs until its manager stops the system, or the timeout. By default on the wall clock, each
 * agent on its own thread, as Jason's test framework runs; with simulated time, a test file runs in
 * stepping mode and its clock jumps to the next timer when every agent is idle ({@link
 * LocalMAS#runSimulated}), so that a {@code .wait(300)} before an assertion holds however loaded the
 * machine is. A test project keeps the wall clock: its environment may act on threads of its own.
 */
public final class AslTestRunner {
    /** Prepares a project before it is loaded (its artifacts' classes); a failure is the unit's error. */
    public interface ProjectSetup {
        void prepare(Path mas2j) throws Exception;
    }

    /**
     * The outcome of one unit: its tests, one per assertion line, and the test manager's own summary
     * line when it printed one. Jason's manager counts an assertion repeated with the same values
     * (a loop) once, so the unit's counts are the manager's when it printed them, plus the errors.
     */
    public record UnitResult(Path file, List<AslTestCase> cases, String managerSummary, int managerExecuted,
            int managerPassed, long millis) {
        public long passed() {
            return managerSummary != null ? managerPassed : lines(Status.PASSED);
        }

        public long failed() {
            return (managerSummary != null ? managerExecuted - managerPassed : lines(Status.FAILED)) + lines(Status.ERROR);
        }

        /** {@return whether the assertion lines differ from the manager's count} */
        public boolean managerCountsOtherwise() {
            return managerSummary != null
                    && (managerExecuted != lines(Status.PASSED) + lines(Status.FAILED) || managerPassed != lines(Status.PASSED));
        }

        public long lines(Status status) {
            return cases.stream().filter(c -> c.status() == status).count();
        }
    }

    private static final Pattern TEST_LABEL = Pattern.compile("@[\\w]*\\[[^\\]]*\\btest\\b");
    private static final Set<String> SKIPPED_DIRS = Set.of("build", "bin", "out", "target", "node_modules");

    private final Consumer<String> echo;
    private final Duration timeout;
    private final long seed;
    private final ProjectSetup setup;
    private final boolean simulatedTime;

    /** @param echo where the agents' console lines go as well (null: nowhere) */
    public AslTestRunner(Consumer<String> echo, Duration timeout, long seed, ProjectSetup setup) {
        this(echo, timeout, seed, setup, false);
    }

    /** @param simulatedTime whether test files run on simulated time (test projects keep the wall clock) */
    public AslTestRunner(Consumer<String> echo, Duration timeout, long seed, ProjectSetup setup, boolean simulatedTime) {
        this.echo = echo;
        this.timeout = timeout;
        this.seed = seed;
        this.setup = setup;
        this.simulatedTime = simulatedTime;
    }

    /**
     * The units under the given files and folders, sorted: every test project ({@code .mas2j}
     * naming a {@code test_manager}) and every test file not inside a project's folder.
     */
    public static List<Path> discover(List<Path> roots) throws IOException {
        var units = new TreeSet<Path>();
        for (Path root : roots) {
            if (Files.isRegularFile(root)) {
                units.add(root.normalize());
                continue;
            }
            if (!Files.isDirectory(root)) {
                throw new IOException(root + ": no such file or folder");
            }
            var files = new ArrayList<Path>();
            try (Stream<Path> walk = Files.walk(root)) {
                walk.filter(p -> Files.isRegularFile(p) && !skipped(root, p)).forEach(files::add);
            }
            var projectDirs = new ArrayList<Path>();
            for (Path p : files) {
                if (p.toString().endsWith(".mas2j")) {
                    projectDirs.add(p.getParent());
                    if (isTestProject(p)) {
                        units.add(p.normalize());
                    }
                }
            }
            for (Path p : files) {
                if (p.toString().endsWith(".asl") && projectDirs.stream().noneMatch(p::startsWith) && isTestFile(p)) {
                    units.add(p.normalize());
                }
            }
        }
        return List.copyOf(units);
    }

    private static boolean skipped(Path root, Path p) {
        for (Path part : root.relativize(p)) {
            String s = part.toString();
            if (s.startsWith(".") && !s.equals(".") && !s.equals("..") || SKIPPED_DIRS.contains(s)) {
                return true;
            }
        }
        return false;
    }

    static boolean isTestProject(Path mas2j) throws IOException {
        return Files.readString(mas2j, StandardCharsets.UTF_8).contains("test_manager");
    }

    static boolean isTestFile(Path asl) throws IOException {
        String text = Files.readString(asl, StandardCharsets.UTF_8);
        return text.contains("tester_agent.asl") && TEST_LABEL.matcher(text).find();
    }

    /** Runs one unit (a test file or a test project) to its end. */
    public UnitResult run(Path file) {
        var parser = new TestConsoleParser();
        long start = System.nanoTime();
        var console = new PrintStream(new LineTap(parser, echo), true, StandardCharsets.UTF_8);
        String problem = null;
        try {
            boolean project = file.toString().endsWith(".mas2j");
            LocalMAS mas = project ? loadProject(file, console) : loadTestFile(file, console);
            problem = runBounded(mas, simulatedTime && !project);
        } catch (MasLauncher.UserError e) {
            problem = e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            problem = "interrupted";
        } catch (Exception e) {
            problem = e.getClass().getSimpleName() + ": " + e.getMessage();
        }
        console.flush();
        var cases = new ArrayList<>(parser.cases());
        if (problem != null) {
            cases.add(new AslTestCase("", "(run)", null, Status.ERROR, problem));
        } else if (cases.isEmpty() && parser.summary == null) {
            cases.add(new AslTestCase("", "(run)", null, Status.ERROR,
                    parser.fatal ? "the test manager was told of a fatal error" : "no test ran"));
        } else if (parser.fatal) {
            cases.add(new AslTestCase("", "(run)", null, Status.ERROR, "the test manager was told of a fatal error"));
        }
        long ms = (System.nanoTime() - start) / 1_000_000;
        return new UnitResult(file, List.copyOf(cases), parser.summary, parser.summaryExecuted, parser.summaryPassed, ms);
    }

    private LocalMAS loadProject(Path file, PrintStream console) throws Exception {
        if (setup != null) {
            setup.prepare(file);
        }
        return new MasLauncher(console, seed, false).includes(AslTestLibrary::resolver).load(file);
    }

    private LocalMAS loadTestFile(Path file, PrintStream console) throws Exception {
        var mas = new LocalMAS(Clock.wall(), console, seed);
        mas.setEnvironment(new DefaultEnvironment(), List.of());
        Path dir = file.toAbsolutePath().getParent();
        var parser = new AslParser(List.of(dir), AslTestLibrary.resolver(List.of(dir)));
        try {
            mas.createAgent("test_manager", parser.parse(AslTestLibrary.library("test_manager.asl")), parser, null);
            mas.createAgent(MasLauncher.agentNameFor(file), parser.parseFile(file), parser, MockingArch::new);
        } catch (AslSyntaxException e) {
            throw new MasLauncher.UserError(e.getMessage());
        }
        return mas;
    }

    /** {@return null when the system stopped by itself within the timeout, else why not} */
    private String runBounded(LocalMAS mas, boolean simulated) throws InterruptedException {
        var timedOut = new boolean[1];
        Thread watchdog = new Thread(() -> {
            try {
                Thread.sleep(timeout.toMillis());
                timedOut[0] = true;
                mas.stop();
            } catch (InterruptedException e) {
                // the run ended first
            }
        }, "asl-test-timeout");
        watchdog.setDaemon(true);
        watchdog.start();
        boolean couldGoOn = true;
        if (simulated) {
            couldGoOn = mas.runSimulated(new SimulatedTime());
        } else {
            mas.runThreads();
        }
        watchdog.interrupt();
        watchdog.join();
        if (timedOut[0]) {
            return "timed out after " + timeout.toSeconds() + " s (the test manager did not stop the system)";
        }
        // on the wall clock the run would wait for the timeout: nothing is left to happen
        return couldGoOn ? null : "every agent idle and no timer due in simulated time: nothing more could happen "
                + "(the test manager did not stop the system)";
    }

    /** Splits the console into lines for the parser, and echoes them. */
    private static final class LineTap extends OutputStream {
        private final TestConsoleParser parser;
        private final Consumer<String> echo;
        private final ByteArrayOutputStream line = new ByteArrayOutputStream();

        LineTap(TestConsoleParser parser, Consumer<String> echo) {
            this.parser = parser;
            this.echo = echo;
        }

        @Override
        public synchronized void write(int b) {
            if (b == '\n') {
                String text = line.toString(StandardCharsets.UTF_8);
                line.reset();
                parser.line(text.endsWith("\r") ? text.substring(0, text.length() - 1) : text);
                if (echo != null) {
                    echo.accept(text);
                }
            } else {
                line.write(b);
            }
        }
    }
}
