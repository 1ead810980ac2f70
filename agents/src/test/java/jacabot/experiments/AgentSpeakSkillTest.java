package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.AslTestCase;
import jacabot.agent.testing.AslTestRunner;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicContainer;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The AgentSpeak skill tests of {@code src/test/asl} (tester agents with mocked artifact
 * operations), run as {@code jacabot test agents/src/test/asl} runs them: each assertion is a
 * JUnit test of its own, so that they count in {@code gradle test}'s "N passed, M failed".
 */
class AgentSpeakSkillTest {
    @TestFactory
    Stream<DynamicNode> eachAgentSpeakTestPasses() throws Exception {
        Path dir = Path.of(System.getProperty("jacabot.projectDir", ".")).resolve("src/test/asl");
        List<Path> units = AslTestRunner.discover(List.of(dir));
        assertFalse(units.isEmpty(), "AgentSpeak tests in " + dir);
        var runner = new AslTestRunner(null, Duration.ofSeconds(60), 0, null, true);
        var nodes = new ArrayList<DynamicNode>();
        for (Path unit : units) {
            AslTestRunner.UnitResult r = runner.run(unit);
            var tests = new ArrayList<DynamicTest>();
            int n = 0;
            for (AslTestCase c : r.cases()) {
                n++;
                String name = c.test() + (c.assertion() == null ? "" : " " + c.assertion()) + " #" + n;
                tests.add(DynamicTest.dynamicTest(name, () -> assertTrue(c.passed(), c.message())));
            }
            tests.add(DynamicTest.dynamicTest("the test manager's count", () -> {
                assertTrue(r.managerSummary() != null, "the test manager printed its summary");
                assertEquals(r.cases().size(), r.managerExecuted(), r.managerSummary());
            }));
            nodes.add(DynamicContainer.dynamicContainer(unit.getFileName().toString(), tests));
        }
        return nodes.stream();
    }
}
