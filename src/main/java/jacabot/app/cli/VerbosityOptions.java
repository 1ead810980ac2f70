package jacabot.app.cli;

import jacabot.app.console.ConsoleLog;
import jacabot.app.console.Verbosity;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/** {@code --quiet} and {@code --verbose}, shared by the commands that run agents. */
final class VerbosityOptions {
    @Option(names = {"-q", "--quiet"}, description = "only the results, warnings and errors")
    boolean quiet;

    @Option(names = {"-v", "--verbose"}, description = "every agent line as printed (none folded) and the link's details")
    boolean verbose;

    /** {@return the command's console at the chosen level} @throws UserError when both flags are given */
    ConsoleLog console(CommandSpec spec) {
        try {
            return new ConsoleLog(spec.commandLine().getOut(), spec.commandLine().getErr(), Verbosity.of(quiet, verbose));
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
    }
}
