package jacabot.app.cli;

import jacabot.app.plot.RunPlots;
import jacabot.app.replay.StepLog;
import jacabot.app.replay.TeamRuns;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jacabot plot runs/X}: (re)draws a recorded run's plots next to its trajectory.png; with several runs, overlays them. */
@Command(name = "plot", mixinStandardHelpOptions = true,
        description = {"Draws a recorded run's plots (battery, speed, events, latency) as PNG in its folder.",
                "With several runs (an agent's and a baseline's, two seeds...): their trajectories overlaid in one PNG (--out)."})
final class PlotCommand implements Callable<Integer> {
    @Spec
    private CommandSpec commandSpec;
    /** picocli's writers, so the command can run in-process (tests) without the global streams */
    private PrintStream out;

    @Parameters(arity = "1..*", paramLabel = "DIR", description = "the run's folder (runs/NAME-SEED); several to overlay them")
    private List<Path> dirs;

    @Option(names = "--out", paramLabel = "PNG", description = "several runs: the overlay's file (default overlay.png)")
    private Path overlay = Path.of("overlay.png");

    @Override
    public Integer call() throws Exception {
        out = ConsoleStreams.of(commandSpec.commandLine().getOut());
        if (dirs.size() == 1 && !TeamRuns.robotDirs(dirs.get(0)).isEmpty()) {
            RunPlots.writeTeam(dirs.get(0), out); // a team's run: each robot's plots and every trajectory in one
            return 0;
        }
        if (dirs.size() > 1) {
            OutPlace.file("--out", overlay);
        }
        for (Path dir : dirs) {
            if (!Files.isRegularFile(dir.resolve(StepLog.FILE))) {
                throw new UserError(dir + ": no " + StepLog.FILE
                        + " (written by every `jacabot experiment` run, --baseline included)");
            }
        }
        try {
            if (dirs.size() > 1) {
                RunPlots.overlay(dirs, overlay);
                out.println("Overlay of " + dirs.size() + " runs: " + overlay);
                return 0;
            }
            RunPlots.writeAll(dirs.get(0), out);
        } catch (IOException e) {
            throw new RunFailure(e.getMessage());
        }
        return 0;
    }
}
