package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.bench.WorldBenchmark;
import jacabot.sim.io.WorldFileException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code jacabot bench world}: the simulator alone on the four experiment worlds (was sim-world's SimBenchmark). */
@Command(name = "world", mixinStandardHelpOptions = true,
        description = "The simulator alone: cost of a control step and real-time factor on each experiment world, "
                + "the demo pattern driving (no agent, no link).")
final class BenchWorldCommand implements Callable<Integer> {
    @CommandLine.Spec
    private CommandLine.Model.CommandSpec spec;

    @Option(names = "--duration", paramLabel = "T", description = "simulated time per world (default ${DEFAULT-VALUE})")
    private String duration = "300s";

    @Option(names = "--worlds", paramLabel = "DIR", description = "where the four world files are (default: the installation's worlds/)")
    private Path worlds;

    @Override
    public Integer call() {
        try {
            new WorldBenchmark(worlds != null ? Installation.locate(worlds) : Installation.resolve("worlds"),
                    ExperimentCommand.parseDuration(duration), spec.commandLine().getOut()).run();
            return 0;
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
    }
}
