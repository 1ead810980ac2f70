package jacabot.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.TestAgent;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

class InterpreterBenchmarkTest {
    private static String resource(String name) throws Exception {
        try (InputStream in = InterpreterBenchmark.class.getResourceAsStream("/bench/" + name)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    @Test
    void deepProgramsAreTheirResourceWithTheirLengthAndQueries() throws Exception {
        for (var d : InterpreterBenchmark.DEEP) {
            String program = InterpreterBenchmark.variant(resource(d.resource()), d);
            assertTrue(program.contains("\nlength(" + d.length() + ").\n"), d.name());
            assertTrue(program.contains("\nqueries(" + d.queries() + ").\n"), d.name());
        }
        assertEquals(List.of(100, 200, 400, 800, 1600), InterpreterBenchmark.DEEP.stream()
                .filter(d -> d.queries() == 200).map(InterpreterBenchmark.Deep::length).toList());
    }

    @Test
    void theDeepestChainAndTheDeadEndsAreProvedEndToEnd() throws Exception {
        for (String name : List.of("ancestor.asl", "branches.asl")) {
            // the programs themselves, with few queries: every query must succeed, or the plan fails before `end`
            var d = new InterpreterBenchmark.Deep("t", name, 1600, 3, "");
            var a = new TestAgent(InterpreterBenchmark.variant(resource(name), d));
            a.cycles(100_000);
            assertEquals(List.of("start", "end"), a.printed(), name);
        }
    }
}
