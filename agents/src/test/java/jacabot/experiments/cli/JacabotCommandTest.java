package jacabot.experiments.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

class JacabotCommandTest {
    private static String[] run(String... args) {
        PrintStream out = System.out;
        PrintStream err = System.err;
        var bytesOut = new ByteArrayOutputStream();
        var bytesErr = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(bytesOut, true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(bytesErr, true, StandardCharsets.UTF_8));
            int code = JacabotCommand.execute(args);
            return new String[] {String.valueOf(code), bytesOut.toString(StandardCharsets.UTF_8),
                    bytesErr.toString(StandardCharsets.UTF_8)};
        } finally {
            System.setOut(out);
            System.setErr(err);
        }
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
