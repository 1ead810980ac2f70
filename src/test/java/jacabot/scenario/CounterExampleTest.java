package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** {@code jacabot run examples/counter/counter.mas2j}: the thesis' counter, end to end, agents on threads. */
class CounterExampleTest {
    @Test
    void theUserObservesEveryValueOfTheCounter() throws Exception {
        Path project = Path.of(System.getProperty("jacabot.rootDir", ".")).resolve("examples/counter/counter.mas2j");
        var run = ProjectRun.of(project, 20_000);
        assertTrue(run.mas.isStopped(), "the example ends with .stopMAS");
        List<String> observed = run.console().lines()
                .filter(l -> l.startsWith("[counter_user] observed")).collect(Collectors.toList());
        assertEquals(List.of("[counter_user] observed new value: 0", "[counter_user] observed new value: 1",
                "[counter_user] observed new value: 2", "[counter_user] observed new value: 3"), observed);
        assertTrue(run.console().contains("[counter_user] perceived a tick"));
    }
}
