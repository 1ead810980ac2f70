package jacabot.app.cli;

import jacabot.app.plot.RunPlots;
import jacabot.app.replay.StepLog;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code jacabot plot runs/X}: (re)draws a recorded run's plots next to its trajectory.png. */
@Command(name = "plot", mixinStandardHelpOptions = true,
        description = "Draws a recorded run's plots (battery, speed, events, latency) as PNG in its folder.")
final class PlotCommand implements Callable<Integer> {
    @picocli.CommandLine.Spec
    private picocli.CommandLine.Model.CommandSpec commandSpec;
    /** picocli's writers, so the command can run in-process (tests) without the global streams */
    private PrintStream out;

    @Parameters(index = "0", paramLabel = "DIR", description = "the run's folder (runs/NAME-SEED)")
    private Path dir;

    @Override
    public Integer call() throws Exception {
        out = ConsoleStreams.of(commandSpec.commandLine().getOut());
        if (!Files.isRegularFile(dir.resolve(StepLog.FILE))) {
            throw new UserError(dir + ": no " + StepLog.FILE
                    + " (written by every headless `jacabot experiment` run)");
        }
        try {
            RunPlots.writeAll(dir, out);
        } catch (IOException e) {
            throw new RunFailure(e.getMessage());
        }
        return 0;
    }
}
