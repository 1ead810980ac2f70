package jacabot.app.cli;

import jacabot.agent.testing.AslTestCase;
import jacabot.agent.testing.AslTestRunner;
import jacabot.agent.testing.JUnitXmlReport;
import jacabot.cartago.bridge.ProjectClasses;
import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jacabot test PATH...}: runs AgentSpeak unit tests (Jason's test library) and reports each test. */
@Command(name = "test", mixinStandardHelpOptions = true,
        description = {"Runs the AgentSpeak tests under each PATH: every test file (an .asl including tester_agent.asl, "
                + "with @[test] plans) and every .mas2j test project (one with a test_manager agent).",
                "Prints a line per test (passed / failed with the assertion's message / error with its error_msg) "
                        + "and ends with 'N passed, M failed'; exits 1 when a test failed."})
final class TestCommand implements Callable<Integer> {
    @Parameters(paramLabel = "PATH", arity = "1..*", description = "test files, test projects, or folders to search")
    private List<Path> paths;

    @Option(names = "--junit", paramLabel = "DIR", description = "also write a JUnit XML report per test file or project into DIR")
    private Path junit;

    @Option(names = "--timeout", paramLabel = "SECONDS",
            description = "a test file or project still running after this long fails (default ${DEFAULT-VALUE})")
    private int timeoutSeconds = 60;

    @Option(names = "--seed", description = "seed of the agents' random generators (default ${DEFAULT-VALUE})")
    private long seed = 0;

    @Option(names = "--classpath", paramLabel = "PATH", description = "more class path entries for test projects' artifacts")
    private List<String> classpath = new ArrayList<>();

    @Option(names = "--simulated-time", description = "run each test file on simulated time, in one thread: when every "
            + "agent is idle the clock jumps to the next timer, so .wait(300) takes no real time and the agents have done "
            + "all they could before it ends, however loaded the machine; a run where nothing more can happen ends at once. "
            + "Test projects keep the wall clock. Default: the wall clock, an agent per thread, as Jason's test framework")
    private boolean simulatedTime;

    @Option(names = {"-v", "--verbose"}, description = "also print the agents' console")
    private boolean verbose;

    @Spec
    private CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter out = spec.commandLine().getOut();
        if (timeoutSeconds <= 0) {
            throw new UserError("--timeout must be positive, got " + timeoutSeconds);
        }
        List<Path> units;
        if (junit != null) {
            // told before the tests run, not as an unexpected failure after the first one
            try {
                Files.createDirectories(junit);
            } catch (IOException e) {
                throw new UserError("--junit " + junit + ": cannot make the directory (" + OutPlace.whyNot(e) + ")");
            }
        }
        try {
            units = AslTestRunner.discover(paths);
        } catch (IOException e) {
            throw new UserError(e.getMessage());
        }
        if (units.isEmpty()) {
            throw new UserError("no AgentSpeak test under " + paths + " (a test file includes tester_agent.asl and has "
                    + "@[test] plans; a test project's .mas2j has a test_manager agent)");
        }
        var entries = new ArrayList<Path>();
        classpath.forEach(c -> Arrays.stream(c.split(File.pathSeparator)).filter(e -> !e.isEmpty()).map(Path::of).forEach(entries::add));
        var runner = new AslTestRunner(verbose ? out::println : null, Duration.ofSeconds(timeoutSeconds), seed, mas2j -> {
            var classes = ProjectClasses.prepare(mas2j, entries);
            classes.classpath().warnings().forEach(err::println);
            Thread.currentThread().setContextClassLoader(classes.loader());
        }, simulatedTime);
        long passed = 0;
        long failed = 0;
        for (Path unit : units) {
            String name = unit.toString();
            out.println(name);
            out.flush();
            AslTestRunner.UnitResult r = runner.run(unit);
            for (AslTestCase c : r.cases()) {
                out.println(line(c));
            }
            String manager = r.managerSummary() == null ? "" : "  (test_manager: " + r.managerSummary() + ")";
            out.printf(Locale.ROOT, "  %d passed, %d failed%s%n", r.passed(), r.failed(), manager);
            if (r.managerCountsOtherwise()) {
                out.printf(Locale.ROOT, "  (%d assertion lines, %d passed: the test manager counts an assertion repeated with the same values once)%n",
                        r.lines(AslTestCase.Status.PASSED) + r.lines(AslTestCase.Status.FAILED), r.lines(AslTestCase.Status.PASSED));
            }
            passed += r.passed();
            failed += r.failed();
            if (junit != null) {
                JUnitXmlReport.write(junit, name.replaceAll("\\.(asl|mas2j)$", "").replace(File.separatorChar, '.'), r);
            }
        }
        out.printf(Locale.ROOT, "%d passed, %d failed%n", passed, failed);
        out.flush();
        return failed == 0 ? 0 : 1;
    }

    static String line(AslTestCase c) {
        String what = c.test() + (c.assertion() == null ? "" : " " + c.assertion());
        String who = c.agent().isEmpty() ? "" : c.agent() + " ";
        return switch (c.status()) {
            case PASSED -> "  passed  " + who + what;
            case FAILED -> "  FAILED  " + who + what + ": " + c.message();
            // a message of several lines (each error of a file that does not read) stays under its test
            case ERROR -> "  ERROR   " + who + what + ": " + c.message().replace("\n", "\n          ");
        };
    }

}
