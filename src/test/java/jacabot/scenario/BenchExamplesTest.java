package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The projects of examples/bench, for {@code bench interpreter --project}: each runs to its end
 * on agent threads, prints {@code start} then {@code end} and nothing that goes wrong.
 */
class BenchExamplesTest {
    @TestFactory
    Stream<DynamicTest> eachProjectRunsFromStartToEnd() throws Exception {
        Path dir = Path.of(System.getProperty("jacabot.rootDir", ".")).resolve("examples/bench");
        List<Path> projects;
        try (Stream<Path> files = Files.list(dir)) {
            projects = files.filter(p -> p.toString().endsWith(".mas2j")).sorted().collect(Collectors.toList());
        }
        assertEquals(13, projects.size(), "the projects of " + dir);
        return projects.stream().map(p -> DynamicTest.dynamicTest(p.getFileName().toString(), () -> run(p)));
    }

    private static void run(Path project) throws Exception {
        var run = ProjectRun.of(project, 60_000);
        assertTrue(run.mas.isStopped(), project + " ends with .stopMAS");
        List<String> lines = run.console().lines().collect(Collectors.toList());
        List<String> marks = lines.stream().filter(l -> l.endsWith("] start") || l.endsWith("] end")).collect(Collectors.toList());
        assertEquals(2, marks.size(), String.join("\n", lines));
        assertTrue(marks.get(0).endsWith("start") && marks.get(1).endsWith("end"), String.join("\n", lines));
        assertEquals(marks, lines, "nothing else printed: " + String.join("\n", lines));
    }
}
