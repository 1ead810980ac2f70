package jacabot.app.cli;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/** Runs the launcher in-process with its output captured, for the CLI tests. */
final class CliRun {
    private CliRun() {
    }

    /** {@return exit code, stdout, stderr} */
    static String[] run(String... args) {
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
}
