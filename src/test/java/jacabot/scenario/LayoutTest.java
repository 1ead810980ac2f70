package jacabot.scenario;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The repository keeps the thesis' three layers as modules, each documented. */
class LayoutTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void everyModuleHasItsReadme() {
        for (String module : new String[] {"agent-core", "cartago-lite", "sim-world", "robot-controller", "agents"}) {
            assertTrue(Files.isRegularFile(ROOT.resolve(module).resolve("README.md")), module + "/README.md");
            assertTrue(Files.isRegularFile(ROOT.resolve(module).resolve("build.gradle")), module + "/build.gradle");
        }
    }
}
