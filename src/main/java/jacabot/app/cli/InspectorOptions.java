package jacabot.app.cli;

import jacabot.app.inspector.Inspector;
import java.io.IOException;
import java.io.PrintStream;
import java.util.function.Consumer;
import picocli.CommandLine.Option;

/**
 * The mind inspector's options, shared by the commands that run agents. By default it is on
 * when someone watches (the viewer is open) and off for headless runs, which are batch jobs
 * that end in seconds; {@code --inspector} turns it on anyway, {@code --no-inspector} off.
 */
final class InspectorOptions {
    @Option(names = "--inspector", negatable = true,
            description = "the mind inspector: a web page on 127.0.0.1 showing the agents' minds live "
                    + "(default: on with the viewer, off headless)")
    Boolean inspector;

    @Option(names = "--inspector-port", paramLabel = "PORT",
            description = "the inspector's port (default " + Inspector.DEFAULT_PORT + ", or any free port when taken)")
    int port;

    @Option(names = "--inspector-address", paramLabel = "HOST",
            description = "the address the inspector listens on (default 127.0.0.1, loopback only; its token guards it anywhere)")
    String address;

    /** {@return whether to run the inspector, given the command's default} */
    boolean wanted(boolean byDefault) {
        return inspector != null ? inspector : byDefault;
    }

    /** {@return whether the user asked for it explicitly} */
    boolean asked() {
        return Boolean.TRUE.equals(inspector);
    }

    /**
     * Starts the inspector if wanted and prints its address. {@return it, or null}
     *
     * @param warnings where each refused request is told, a line each (the command's warnings: the user sees who knocked)
     */
    Inspector start(boolean byDefault, String title, PrintStream out, Consumer<String> warnings) throws IOException {
        if (!wanted(byDefault)) {
            return null;
        }
        Inspector i = Inspector.start(address, port);
        i.title(title);
        i.logRefusals(warnings);
        out.println("Mind inspector: " + i.address());
        return i;
    }

    /**
     * After a run: keeps the page up while someone may look at the run's history, until Enter;
     * only when the inspector was asked for and a terminal is there to press Enter.
     */
    void linger(Inspector i, PrintStream out) throws IOException {
        if (i != null && asked() && System.console() != null) {
            out.println("The inspector keeps the run's history at " + i.address() + " ; press Enter to quit.");
            System.in.read();
        }
    }
}
