package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.plot.RunPlots;
import jacabot.app.replay.StepArchive;
import jacabot.app.replay.StepLog;
import jacabot.app.replay.WhatIf;
import jacabot.app.run.AgentSource;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;

/** {@code jacabot replay RUN --what-if T --agent edited.asl}: the checks of its options, the run and what it wrote. */
final class WhatIfRun {
    private WhatIfRun() {
    }

    static int run(Path dir, String at, Path agent, Path worldOption, String duration, Path out, PrintStream console,
            PrintStream err) throws Exception {
        if (agent == null) {
            throw new UserError("--what-if needs --agent FILE: the edited agent");
        }
        long atMs, seconds;
        StepArchive recorded;
        try {
            atMs = Math.round(ExperimentCommand.parseDuration(at) * 1000);
            recorded = StepArchive.open(dir, (t, x, z) -> {
            });
            seconds = duration != null ? Math.round(ExperimentCommand.parseDuration(duration))
                    : (recorded.lastTimeMs() + 999) / 1000;
        } catch (IllegalArgumentException e) {
            throw new UserError("--what-if/--duration: " + e.getMessage());
        } catch (IOException e) {
            throw new UserError(e.getMessage());
        }
        StepLog.Header h = recorded.header();
        if (h.realTime()) {
            throw new UserError(dir + ": " + WhatIf.REAL_TIME_REFUSAL);
        }
        Experiment experiment = Experiment.parse(h.experiment())
                .orElseThrow(() -> new UserError(dir + ": unknown experiment '" + h.experiment() + "' in its step log"));
        Path worldFile = worldOption != null ? worldOption : Installation.resolve(experiment.worldFile());
        SimWorld world;
        try {
            world = SimWorld.of(WorldFileReader.read(worldFile));
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
        if (!world.name().equals(h.world())) {
            throw new UserError(worldFile + ": world '" + world.name() + "', but the run was in '" + h.world()
                    + "'; give its file with --world");
        }
        AgentSource original, edited;
        try {
            original = WhatIf.originalAgent(h, experiment);
            edited = AgentSource.file(agent);
        } catch (IOException e) {
            throw new UserError(e.getMessage());
        }
        Path target = out != null ? out : Path.of(dir.toString().replaceAll("/+$", "") + "-whatif-" + atMs / 1000 + "s");
        OutPlace.directory("--out", target);
        console.printf("What if: %s as recorded up to t=%.2f s (seed %d), then the plans of %s; %d s into %s%n", dir,
                atMs / 1000.0, h.seed(), agent, seconds, target);
        WhatIf.Result r;
        try {
            r = WhatIf.run(world, experiment, h.seed(), original, edited, atMs, seconds, target,
                    new PrintStream(OutputStream.nullOutputStream()));
        } catch (IllegalArgumentException e) {
            throw new UserError(agent + ": " + e.getMessage());
        }
        Files.writeString(target.resolve("event-log.txt"), r.recorder().summary("agent").eventLog());
        RunPlots.writeAll(target, console);
        console.printf("Plans swapped at t=%.2f s. Written: %s, event-log.txt, console.txt; compare with: jacabot plot %s %s%n",
                r.swappedAtMs() / 1000.0, target.resolve(StepLog.FILE), dir, target);
        return r.swappedAtMs() < 0 ? 1 : 0;
    }
}
