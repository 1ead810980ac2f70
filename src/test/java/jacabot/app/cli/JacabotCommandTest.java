package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class JacabotCommandTest {
    private static String[] run(String... args) {
        return CliRun.run(args);
    }

    @Test
    void versionComesFromTheBuild() {
        var result = run("--version");
        assertEquals("0", result[0]);
        assertTrue(result[1].matches("jacabot \\d+\\.\\d+\\.\\d+\\R"), result[1]);
    }

    @Test
    void helpListsTheSubcommands() {
        var result = run("--help");
        assertEquals("0", result[0]);
        assertTrue(result[1].contains("experiment"), result[1]);
    }

    @Test
    void anUnknownExperimentIsAUserErrorWithExitCode2() {
        var result = run("experiment", "flying");
        assertEquals("2", result[0]);
        assertTrue(result[2].contains("unknown experiment 'flying'"), result[2]);
    }
}
