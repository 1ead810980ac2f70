package jacabot.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
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
        for (String sub : new String[] {"run", "experiment", "compare", "bench", "controller", "world", "sweep", "replay", "plot", "test", "help"}) {
            assertTrue(result[1].contains("\n  " + sub + " "), sub + " missing from:\n" + result[1]);
        }
    }

    @Test
    void aCommandLineNamingASubcommandBuildsThatOneAlone() {
        assertEquals(Set.of("run"), JacabotCommand.commandLine("run", "x.mas2j").getSubcommands().keySet());
        assertEquals(Set.of("sweep"), JacabotCommand.commandLine("--debug", "sweep", "all").getSubcommands().keySet());
        assertEquals(11, JacabotCommand.commandLine("help", "run").getSubcommands().size());
        assertEquals(11, JacabotCommand.commandLine("--help").getSubcommands().size());
    }

    @Test
    void helpOnASubcommandAndAMistypedOneStillSeeThemAll() {
        var help = run("help", "run");
        assertEquals("0", help[0]);
        assertTrue(help[1].contains("Usage: jacabot run"), help[1]);
        var typo = run("rnu", "x.mas2j");
        assertEquals("2", typo[0]);
        assertTrue(typo[2].startsWith("error: Unmatched arguments from index 0: 'rnu'"), typo[2]);
    }

    @Test
    void anUnknownExperimentIsAUserErrorWithExitCode2() {
        var result = run("experiment", "flying");
        assertEquals("2", result[0]);
        assertTrue(result[2].contains("unknown experiment 'flying'"), result[2]);
    }
}
