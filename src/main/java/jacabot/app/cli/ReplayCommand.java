package jacabot.app.cli;

import jacabot.app.Installation;
import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.MindText;
import jacabot.app.replay.PageEdits;
import jacabot.app.replay.Replay;
import jacabot.app.replay.ReplayViewer;
import jacabot.app.replay.StepArchive;
import jacabot.app.replay.StepLog;
import jacabot.app.replay.TeamRuns;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code jacabot replay runs/X}: plays a recorded run back, with the agent's mind at each instant. */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = {"Plays a recorded run (runs/NAME-SEED, written by every headless experiment) back: "
                + "the viewer with play/pause/step/speed and a time slider, and the mind inspector at the same instant.",
                "Headless (no display, or --headless): prints a summary, the mind at --at T, and --frames N as PNG."},
        footer = {"", "Debugging a failing run (more in the page's help and docs/running.md):",
                "  1. Find the moment: jacabot replay runs/NAME-SEED --headless --inspector;",
                "     open the address it prints, find a line the robot printed in the",
                "     console panel and click it: the header's t= is the instant.",
                "  2. Break there: jacabot experiment NAME --headless --break 't=60s'",
                "     (or 'label:PLAN', '+!goal', 'failure'); the run halts and reads",
                "     commands: Enter continue, s step, n cycle, p print, q no more halts.",
                "  3. Change a plan in a copy of the agent (edited.asl), or in the page's",
                "     What if panel; a live run takes it from there too, halted in lockstep,",
                "     or running: jacabot experiment NAME --real-time --headless",
                "  4. What if: jacabot replay runs/NAME-SEED --what-if 60s --agent edited.asl",
                "     then: jacabot plot runs/NAME-SEED runs/NAME-SEED-whatif-60s --out both.png"})
final class ReplayCommand implements Callable<Integer> {
    @Spec
    private CommandSpec commandSpec;
    /** picocli's writers, so the command can run in-process (tests) without the global streams */
    private PrintStream out;
    private PrintStream err;

    @Parameters(index = "0", paramLabel = "DIR", description = "the run's folder (or its steps.jsonl.gz)")
    private Path dir;

    @Option(names = "--headless", description = "no window: print a summary (the default without a display)")
    private boolean headless;

    @Option(names = "--at", paramLabel = "T", description = "headless: print the agent's mind at this simulated time (90s, 2m)")
    private String at;

    @Option(names = "--frames", paramLabel = "N", description = "headless: render N frames evenly over the run into DIR/frames/")
    private int frames;

    @Option(names = "--what-if", paramLabel = "T", description = "a new run, the same as this one up to T (90s, 2m), "
            + "then with --agent's plans instead of the agent's; written into --out")
    private String whatIf;

    @Option(names = "--agent", paramLabel = "FILE", description = "with --what-if: the edited agent")
    private Path agent;

    @Option(names = "--world", paramLabel = "FILE", description = "with --what-if: the run's world file (default: the experiment's)")
    private Path world;

    @Option(names = "--duration", paramLabel = "D", description = "with --what-if: how long the new run goes (default: as long as this one)")
    private String duration;

    @Option(names = "--out", paramLabel = "DIR", description = "with --what-if: where it goes (default DIR-whatif-T)")
    private Path outDir;

    @Mixin
    private InspectorOptions inspectorOptions = new InspectorOptions();

    @Override
    public Integer call() throws Exception {
        out = ConsoleStreams.of(commandSpec.commandLine().getOut());
        err = ConsoleStreams.of(commandSpec.commandLine().getErr());
        if (whatIf != null) {
            return WhatIfRun.run(dir, whatIf, agent, world, duration, outDir, out, err);
        }
        boolean window = !headless && !GraphicsEnvironment.isHeadless();
        List<Path> team = TeamRuns.robotDirs(dir);
        if (!team.isEmpty() && !(!window && inspectorOptions.asked())) {
            throw new UserError(dir + " is a team's run: replay one robot's folder (" + team.get(0)
                    + "), or every robot's mind with --headless --inspector");
        }
        if (!window && inspectorOptions.asked()) {
            try {
                return serve(); // reads the step log on demand, not all of it into memory
            } catch (IOException e) {
                throw new UserError(e.getMessage());
            }
        }
        if (frames < 0) {
            throw new UserError("--frames " + frames + ": a number of pictures, 1 or more");
        }
        Long atMs = null;
        if (at != null) {
            // told before the step log is read, not after its summary
            try {
                atMs = Math.round(ExperimentCommand.parseDuration(at) * 1000);
            } catch (IllegalArgumentException e) {
                throw new UserError("--at: " + e.getMessage());
            }
        }
        Replay replay;
        try {
            replay = Replay.open(dir);
        } catch (IOException e) {
            throw new UserError(e.getMessage());
        }
        if (replay.frames().isEmpty()) {
            throw new UserError(dir + ": the step log has no step");
        }
        long endMs = replay.frames().get(replay.frames().size() - 1).timeMs() + replay.header().controlStep();
        if (atMs != null && atMs > endMs) {
            // the last step is one control step before the end its summary tells (599.96 s of a 600 s run)
            throw new UserError(String.format("--at %s: after the run's end (%.1f s simulated)", at, endMs / 1000.0));
        }
        if (!window) {
            return headlessReplay(replay, atMs);
        }
        Inspector inspector = inspectorOptions.start(true, "replay of " + dir, out, this::warn);
        var history = inspector == null ? null : inspector.add("robot");
        if (inspector != null) {
            inspector.showPlots(Files.isDirectory(dir) ? dir : dir.getParent());
            inspector.console(ConsoleFile.of(Files.isDirectory(dir) ? dir : dir.toAbsolutePath().getParent()));
        }
        var closed = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            var frame = ReplayViewer.open(replay, i -> {
                if (history != null) {
                    history.record(replay.frames().get(i).mind(), replay.robotView(i), List.of());
                }
            });
            frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
            frame.addWindowListener(new WindowAdapter() {
                @Override
                public void windowClosed(WindowEvent e) {
                    closed.countDown();
                }
            });
        });
        closed.await();
        if (inspector != null) {
            inspector.close();
        }
        return 0;
    }

    /** A warning line on the command's error stream (as a run's {@code warning: ...}). */
    private void warn(String line) {
        err.println("warning: " + line);
        err.flush();
    }

    /** Headless with {@code --inspector}: the recorded run in the inspector's page, read on demand, until Enter or Ctrl-C. */
    private int serve() throws Exception {
        Inspector inspector = inspectorOptions.start(true, "replay of " + dir, out, this::warn);
        try {
            if (!TeamRuns.robotDirs(dir).isEmpty()) {
                return serveTeam(inspector);
            }
            var archive = StepArchive.show(inspector, dir);
            inspector.console(ConsoleFile.of(Files.isDirectory(dir) ? dir : dir.toAbsolutePath().getParent()));
            try { // what-ifs from the page
                StepLog.Header h = archive.header();
                Experiment experiment = Experiment.parse(h.experiment()).orElse(null);
                Path worldFile = world != null ? world
                        : experiment == null ? null : Installation.resolve(experiment.worldFile());
                inspector.edits(PageEdits.recorded(inspector, dir, h, () -> SimWorld.of(WorldFileReader.read(worldFile))));
            } catch (IOException e) {
                out.println("No what-if from the page: " + e.getMessage());
            }
            out.printf("The recorded run, %.1f s to %.1f s, is served at %s ; %s%n", archive.firstTimeMs() / 1000.0,
                    archive.lastTimeMs() / 1000.0, inspector.address(),
                    System.console() != null ? "press Enter to quit." : "Ctrl-C to quit.");
            awaitQuit();
        } finally {
            inspector.close();
        }
        return 0;
    }

    /** A team's run: every robot's agent in the page, its history read on demand (no what-if: a team's is not built). */
    private int serveTeam(Inspector inspector) throws Exception {
        var first = TeamRuns.show(inspector, dir);
        inspector.console(ConsoleFile.of(dir)); // the team's console.txt: every agent's lines, named
        out.printf("The recorded team run, %d robots, %.1f s to %.1f s, is served at %s ; %s%n", TeamRuns.robotDirs(dir).size(),
                first.firstTimeMs() / 1000.0, first.lastTimeMs() / 1000.0, inspector.address(),
                System.console() != null ? "press Enter to quit." : "Ctrl-C to quit.");
        awaitQuit();
        return 0;
    }

    /**
     * The address now, not when the process ends; then serves until Enter (or Ctrl-C without a
     * terminal). An interrupt of the command's thread (a caller running it in-process) is a quit too.
     */
    private void awaitQuit() throws IOException {
        out.flush();
        commandSpec.commandLine().getOut().flush();
        if (System.console() != null) {
            System.in.read();
            return;
        }
        try {
            new CountDownLatch(1).await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private int headlessReplay(Replay replay, Long atMs) throws IOException {
        var h = replay.header();
        var all = replay.frames();
        var last = all.get(all.size() - 1);
        var plans = new TreeMap<String, Integer>();
        double distance = 0;
        for (int i = 0; i < all.size(); i++) {
            var f = all.get(i);
            if (i > 0) {
                var p = all.get(i - 1).body();
                distance += Math.hypot(f.body().x() - p.x(), f.body().z() - p.z());
            }
            for (MindState.Selection s : f.mind().selections()) {
                plans.merge(s.plan(), 1, Integer::sum);
            }
        }
        out.printf("Replay of %s: experiment %s, world %s, seed %d, robot %s, agent %s%n", dir, h.experiment(),
                h.world(), h.seed(), h.robot(), h.agentFile());
        out.printf("%d control steps of %d ms, %.1f s simulated, %.2f m travelled, %d reasoning cycles%n", all.size(),
                h.controlStep(), last.timeMs() / 1000.0, distance, last.mind().cycle());
        out.printf("end: x %.3f z %.3f heading %.1f, battery %s, holding %s%n", last.body().x(), last.body().z(),
                last.body().heading(), last.body().battery() == null ? "-" : String.format("%.0f J", last.body().battery()),
                last.body().held() == null ? "nothing" : last.body().held());
        int selections = plans.values().stream().mapToInt(Integer::intValue).sum();
        out.printf("mind: %d beliefs at the end, %d plan selections, %d distinct plans%n", last.mind().beliefs().size(),
                selections, plans.size());
        plans.entrySet().stream().sorted(Map.Entry.<String, Integer>comparingByValue().reversed()).limit(5)
                .forEach(e -> out.printf("  %6d x %s%n", e.getValue(), e.getKey()));
        if (atMs != null) {
            printMind(replay, replay.indexAt(atMs));
        }
        if (frames > 0) {
            Path frameDir = (Files.isDirectory(dir) ? dir : dir.getParent()).resolve("frames");
            Files.createDirectories(frameDir);
            for (int k = 0; k < frames; k++) {
                int i = frames == 1 ? all.size() - 1 : (int) ((long) k * (all.size() - 1) / (frames - 1));
                ImageIO.write(ReplayViewer.render(replay, i, 640, 640), "png",
                        frameDir.resolve(String.format("frame-%04d.png", k + 1)).toFile());
            }
            out.println("Frames: " + frames + " PNG in " + frameDir);
        }
        return 0;
    }

    private void printMind(Replay replay, int i) {
        out.println();
        MindText.print(replay.frames().get(i).mind(), out);
    }
}
