package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** {@code jacabot run examples/counter/counter.mas2j}: the thesis' counter, end to end, agents on threads. */
class CounterExampleTest {
    @Test
    void theUserObservesEveryValueOfTheCounter() throws Exception {
        Path project = Path.of(System.getProperty("jacabot.rootDir", ".")).resolve("examples/counter/counter.mas2j");
        var bytes = new ByteArrayOutputStream();
        var mas = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, false).load(project);
        Thread t = new Thread(() -> {
            try {
                mas.runThreads();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        t.setDaemon(true);
        t.start();
        t.join(20_000);
        assertTrue(mas.isStopped(), "the example ends with .stopMAS");
        List<String> observed = bytes.toString(StandardCharsets.UTF_8).lines()
                .filter(l -> l.startsWith("[counter_user] observed")).collect(Collectors.toList());
        assertEquals(List.of("[counter_user] observed new value: 0", "[counter_user] observed new value: 1",
                "[counter_user] observed new value: 2", "[counter_user] observed new value: 3"), observed);
        assertTrue(bytes.toString(StandardCharsets.UTF_8).contains("[counter_user] perceived a tick"));
    }
}
