package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.testing.AslTestCase;
import jacabot.agent.testing.AslTestRunner;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The skill test that agents/README.md shows ("Testing skills") passes as written there: copied
 * into a {@code src/test/asl} folder beside the agents' {@code src/main/asl}, as its include expects.
 */
class ReadmeSkillTestTest {
    @Test
    void theReadmesSkillTestPassesAsWritten(@TempDir Path dir) throws Exception {
        Path project = Path.of(System.getProperty("jacabot.projectDir", "."));
        String readme = Files.readString(project.resolve("README.md"));
        int start = readme.indexOf("```\n{ include(\"tester_agent.asl\") }") + 4;
        assertTrue(start > 4, "agents/README.md shows a tester agent");
        String test = readme.substring(start, readme.indexOf("```", start));
        Files.createDirectories(dir.resolve("src/test/asl"));
        Files.createDirectories(dir.resolve("src/main"));
        Files.createSymbolicLink(dir.resolve("src/main/asl"), project.resolve("src/main/asl").toAbsolutePath());
        Path unit = Files.writeString(dir.resolve("src/test/asl/readme_test.asl"), test);
        List<AslTestCase> cases = new AslTestRunner(null, Duration.ofSeconds(60), 0, null, true).run(unit).cases();
        assertFalse(cases.isEmpty());
        for (AslTestCase c : cases) {
            assertTrue(c.passed(), c.test() + ": " + c.message());
        }
    }
}
