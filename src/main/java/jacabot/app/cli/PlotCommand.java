package jacabot.app.cli;

import jacabot.app.plot.RunPlots;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code jacabot plot runs/X}: (re)draws a recorded run's plots next to its trajectory.png. */
@Command(name = "plot", mixinStandardHelpOptions = true,
        description = "Draws a recorded run's plots (battery, speed, events, latency) as PNG in its folder.")
final class PlotCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "DIR", description = "the run's folder (runs/NAME-SEED)")
    private Path dir;

    @Override
    public Integer call() throws Exception {
        if (!Files.isRegularFile(dir.resolve(jacabot.app.replay.StepLog.FILE))) {
            System.err.println("error: " + dir + ": no " + jacabot.app.replay.StepLog.FILE
                    + " (written by every headless `jacabot experiment` run)");
            return 2;
        }
        try {
            RunPlots.writeAll(dir, System.out);
        } catch (java.io.IOException e) {
            System.err.println("error: " + e.getMessage());
            return 1;
        }
        return 0;
    }
}
