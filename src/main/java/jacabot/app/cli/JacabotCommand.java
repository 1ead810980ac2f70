package jacabot.app.cli;

import jacabot.app.world.WorldGenerator;
import jacabot.experiments.link.LinkRegistry;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import picocli.CommandLine.Command;
import picocli.CommandLine;

/** The {@code jacabot} launcher: one entry point with a subcommand per job. */
@Command(name = "jacabot",
        mixinStandardHelpOptions = true,
        versionProvider = JacabotCommand.Version.class,
        description = "JaCa-style BDI robots in a simulated world: companion code to the thesis "
                + "'Programming Robots with an Agent-Oriented BDI-based Control Architecture'.")
public final class JacabotCommand implements Runnable {
    /**
     * The subcommands, in the order of the usage text. picocli reads a command's annotations and
     * fields when it is added: for the eight a run does not need, about 35 ms of its 330 ms to its
     * first output. So a command line naming one gets that one alone ({@link #commandLine(String...)}).
     */
    private static final List<Class<?>> SUBCOMMANDS = List.of(RunCommand.class, ExperimentCommand.class,
            CompareCommand.class, BenchCommand.class, ControllerCommand.class, WorldCommand.class, SweepCommand.class,
            ReplayCommand.class, PlotCommand.class, TestCommand.class, CommandLine.HelpCommand.class);

    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    @CommandLine.Option(names = "--debug", scope = CommandLine.ScopeType.INHERIT,
            description = "print the stack trace of an unexpected failure")
    private boolean debug;

    public static void main(String[] args) {
        // An agent's thread that dies (e.g. StackOverflowError in a runaway rule) must not leave a
        // process that looks alive: say so and end with 1 (the shutdown hooks write what they have).
        Thread.setDefaultUncaughtExceptionHandler((thread, e) -> {
            System.err.println("error: thread '" + thread.getName() + "' died: " + describe(e)
                    + "; stopping (exit 1)");
            if (List.of(args).contains("--debug")) {
                e.printStackTrace();
            }
            LinkRegistry.closeAll(); // the robots stop now, not when the JVM is gone
            new Thread(() -> System.exit(1), "exit-after-thread-death").start();
        });
        System.exit(execute(args));
    }

    /** Runs the launcher and returns its exit code (0 ok, 1 runtime failure, 2 user error). */
    public static int execute(String... args) {
        return commandLine(args).execute(args);
    }

    /**
     * {@return the launcher's command line}: a user error prints one line and exits with 2, a run
     * failure one line and 1, a stack trace only with {@code --debug}. Tests set its out and err
     * ({@code setOut}/{@code setErr}) instead of the global streams.
     */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new JacabotCommand());
        for (Class<?> sub : SUBCOMMANDS) {
            cl.addSubcommand(sub);
        }
        return withHandlers(cl);
    }

    /**
     * {@return the launcher's command line for these arguments}: with only the subcommand they
     * name, or every subcommand when they name none of them (help, a mistyped name, no name).
     */
    public static CommandLine commandLine(String... args) {
        Class<?> named = namedSubcommand(args);
        if (named == null) {
            return commandLine();
        }
        CommandLine cl = new CommandLine(new JacabotCommand());
        cl.addSubcommand(isTeam(args) ? TEAM_COMMANDS.getOrDefault(named, named) : named);
        return withHandlers(cl);
    }

    /** The team's own commands, of the same names: {@code experiment team-delivery}, {@code sweep team-delivery}. */
    private static final Map<Class<?>, Class<?>> TEAM_COMMANDS = Map.of(ExperimentCommand.class, TeamExperimentCommand.class,
            SweepCommand.class, TeamSweepCommand.class);

    /** {@return whether the subcommand's first argument that is not an option is team-delivery} */
    private static boolean isTeam(String[] args) {
        int words = 0;
        for (String a : args) {
            if (!a.startsWith("-") && ++words == 2) {
                return a.equals(WorldGenerator.TEAM_DELIVERY);
            }
        }
        return false;
    }

    /** {@return the subcommand the first argument that is not an option names, or null} */
    private static Class<?> namedSubcommand(String[] args) {
        for (String a : args) {
            if (a.startsWith("-")) {
                continue; // --debug, the one option before a subcommand that takes no value
            }
            for (Class<?> sub : SUBCOMMANDS) {
                Command c = sub.getAnnotation(Command.class);
                if (c != null && c.name().equals(a) && sub != CommandLine.HelpCommand.class) {
                    return sub;
                }
            }
            return null;
        }
        return null;
    }

    private static CommandLine withHandlers(CommandLine cl) {
        cl.setParameterExceptionHandler((ex, args) -> {
            CommandLine c = ex.getCommandLine();
            String guess = "";
            if (ex instanceof CommandLine.UnmatchedArgumentException u && !u.getSuggestions().isEmpty()) {
                // picocli's own suggestions: the options and subcommands nearest to what was typed
                List<String> near = u.getSuggestions();
                guess = "; did you mean " + String.join(" or ", near.subList(0, Math.min(3, near.size()))) + "?";
            }
            c.getErr().println("error: " + ex.getMessage() + guess + " (see: " + c.getCommandSpec().qualifiedName() + " --help)");
            c.getErr().flush();
            return 2;
        });
        cl.setExecutionExceptionHandler((ex, c, parseResult) -> {
            boolean debug = parseResult.expandedArgs().contains("--debug");
            if (ex instanceof UserError || ex instanceof RunFailure) {
                c.getErr().println(ex instanceof UserError u ? u.line() : "error: " + ex.getMessage());
                c.getErr().flush();
                return ex instanceof UserError ? 2 : 1;
            }
            c.getErr().println("error: " + describe(ex) + (debug ? "" : " (--debug shows the stack trace)"));
            if (debug) {
                ex.printStackTrace(c.getErr());
            }
            c.getErr().flush();
            return 1;
        });
        return cl;
    }

    /** {@return the exception's message, or its type when it has none} */
    static String describe(Throwable e) {
        String m = e.getMessage();
        String type = e.getClass().getSimpleName();
        if (e instanceof StackOverflowError) {
            return "StackOverflowError (a rule or plan that recurses without end?)";
        }
        if (e instanceof OutOfMemoryError) {
            return "OutOfMemoryError: " + m;
        }
        return m == null || m.isBlank() ? type : (e instanceof RuntimeException && !(e instanceof UserError)
                && !(e instanceof IllegalArgumentException) && !(e instanceof IllegalStateException) ? type + ": " + m : m);
    }

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
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
