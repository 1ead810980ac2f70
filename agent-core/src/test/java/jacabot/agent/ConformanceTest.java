package jacabot.agent;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The conformance corpus: each program prints exactly the lines Jason 3.2.0 printed for it.
 * Runs each program in both run modes (a thread per agent, and deterministic stepping).
 */
class ConformanceTest {
    private static final Pattern CONSOLE_LINE = Pattern.compile("^\\[[A-Za-z0-9_]+\\] .*");

    static Path corpus(String name) throws URISyntaxException {
        return Path.of(ConformanceTest.class.getResource("/" + name).toURI());
    }

    @TestFactory
    Stream<DynamicTest> corpusWithAgentThreads() throws Exception {
        return tests("conformance", 45, false);
    }

    @TestFactory
    Stream<DynamicTest> corpusInSteppingMode() throws Exception {
        return tests("conformance", 45, true);
    }

    /** More programs, whose expected lines were printed by Jason 3.2.0 itself (see its README). */
    @TestFactory
    Stream<DynamicTest> jasonOracleWithAgentThreads() throws Exception {
        return tests("jason-oracle", 66, false);
    }

    @TestFactory
    Stream<DynamicTest> jasonOracleInSteppingMode() throws Exception {
        return tests("jason-oracle", 66, true);
    }

    private Stream<DynamicTest> tests(String corpus, int size, boolean stepping) throws Exception {
        List<Path> programs;
        try (Stream<Path> files = Files.list(corpus(corpus))) {
            programs = files.filter(p -> p.getFileName().toString().matches("\\d{2,3}_.*\\.asl")).sorted().collect(Collectors.toList());
        }
        assertTrue(programs.size() >= size, "the corpus " + corpus + " is complete");
        return programs.stream().map(p -> DynamicTest.dynamicTest(p.getFileName().toString(), () -> check(p, stepping)));
    }

    static List<String> run(Path program, boolean stepping) throws Exception {
        var bytes = new ByteArrayOutputStream();
        var out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        var launcher = new MasLauncher(out, 0, stepping);
        var mas = launcher.load(program);
        Thread runner = new Thread(() -> {
            try {
                if (stepping) {
                    mas.runStepping();
                } else {
                    mas.runThreads();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        runner.setDaemon(true);
        runner.start();
        runner.join(TimeUnit.SECONDS.toMillis(20));
        assertTrue(mas.isStopped(), program.getFileName() + " did not reach .stopMAS within 20 s");
        return bytes.toString(StandardCharsets.UTF_8).lines()
                .filter(l -> CONSOLE_LINE.matcher(l).matches()).collect(Collectors.toList());
    }

    private static void check(Path program, boolean stepping) throws Exception {
        Path expected = program.resolveSibling(program.getFileName().toString().replace(".asl", ".expected"));
        List<String> want = Files.readAllLines(expected, StandardCharsets.UTF_8);
        assertEquals(String.join("\n", want), String.join("\n", run(program, stepping)));
    }
}
