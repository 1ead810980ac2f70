package jacabot.app.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The {@code jacabot} launcher: one entry point with a subcommand per job. */
@Command(name = "jacabot",
        mixinStandardHelpOptions = true,
        versionProvider = JacabotCommand.Version.class,
        description = "JaCa-style BDI robots in a simulated world: companion code to the thesis "
                + "'Programming Robots with an Agent-Oriented BDI-based Control Architecture'.",
        subcommands = {RunCommand.class, ExperimentCommand.class, CompareCommand.class, BenchCommand.class, ControllerCommand.class, WorldCommand.class, SweepCommand.class, CommandLine.HelpCommand.class})
public final class JacabotCommand implements Runnable {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /** Runs the launcher and returns its exit code (0 ok, 1 runtime failure, 2 user error). */
    public static int execute(String... args) {
        return new CommandLine(new JacabotCommand()).execute(args);
    }

    @Override
    public void run() {
        spec.commandLine().usage(System.out);
    }

    /** Reads the build's version from the resource Gradle fills in. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            var props = new Properties();
            try (InputStream in = JacabotCommand.class.getResourceAsStream("/jacabot/version.properties")) {
                if (in != null) {
                    props.load(in);
                }
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            return new String[] {"jacabot " + props.getProperty("version", "unknown")};
        }
    }
}
