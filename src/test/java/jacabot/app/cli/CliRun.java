package jacabot.app.cli;

import java.io.PrintWriter;
import java.io.StringWriter;

/** Runs the launcher in-process through picocli's own writers, for the CLI tests (no global streams touched). */
final class CliRun {
    private CliRun() {
    }

    /** {@return exit code, stdout, stderr} */
    static String[] run(String... args) {
        var out = new StringWriter();
        var err = new StringWriter();
        var cl = JacabotCommand.commandLine(args);
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        return new String[] {String.valueOf(code), out.toString(), err.toString()};
    }
}
