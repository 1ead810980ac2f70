package jacabot.app.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.app.Installation;
import jacabot.app.console.ConsoleLog;
import jacabot.app.inspector.Breakpoint;
import jacabot.app.inspector.ConsoleFile;
import jacabot.app.inspector.ConsoleRecorder;
import jacabot.app.inspector.DebugConsole;
import jacabot.app.inspector.Debugger;
import jacabot.app.plot.RunPlots;
import jacabot.app.plot.TrajectoryPlot;
import jacabot.app.replay.BaselineTap;
import jacabot.app.replay.PageEdits;
import jacabot.app.replay.RunTap;
import jacabot.app.replay.StepLog;
import jacabot.app.run.AgentSource;
import jacabot.app.run.ExperimentMatch;
import jacabot.app.run.LockstepCoordinator;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.RobotAgent;
import jacabot.app.world.Landmarks;
import jacabot.cartago.CartagoException;
import jacabot.robot.Experiment;
import jacabot.robot.baseline.BaselineRunner;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.WorldSpec;
import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.MalformedInputException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.TypeConversionException;

/** {@code jacabot experiment NAME}: runs one of the four experiments of the thesis' Chapter 4, or tidy-up (composed of their skills). */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = {"Runs an experiment of Chapter 4 with the agent in the loop: obstacle-avoidance, "
                + "object-picking, navigation, suspend-resume (or 1-4); or tidy-up (5), a task composed of their skills; "
                + "or team-delivery, a team of robots (its own options: jacabot experiment team-delivery --help).",
                "Headless runs go in lockstep as fast as possible and end with a summary and a PNG of the trajectory."})
final class ExperimentCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", converter = ExperimentConverter.class,
            description = "obstacle-avoidance | object-picking | navigation | suspend-resume | tidy-up")
    private Experiment experiment;

    @Option(names = "--headless", description = "no viewer: lockstep, as fast as possible (the default without a display); "
            + "with --real-time: real time without the viewer")
    private boolean headless;

    @Option(names = "--lockstep", description = "advance the world only when the agent is idle (always on when headless)")
    private boolean lockstep;

    @Option(names = "--real-time", description = "real time (x --speed), the agent running free as in the thesis, also "
            + "without the viewer: with --headless or no display, a server's run watched on the inspector's page (on by default), "
            + "which can apply edited plans to the running agent; --duration or Ctrl-C ends it")
    private boolean realTime;

    @Option(names = "--speed", paramLabel = "X", description = "in real time: real time x this factor (default ${DEFAULT-VALUE})")
    private double speed = 1;

    @Option(names = "--seed", paramLabel = "N", description = "seed of the world and the agent (default: the world file's)")
    private Long seed;

    @Option(names = "--duration", paramLabel = "T", description = "simulated time: 90s, 10m, ... (default ${DEFAULT-VALUE})")
    private String duration = "10m";

    @Option(names = "--world", paramLabel = "FILE", description = "the world file (default worlds/NAME.json)")
    private Path world;

    @Option(names = "--agent", paramLabel = "FILE", description = "the agent (default: the packaged agents/src/main/asl/NAME.asl)")
    private Path agent;

    @Option(names = "--agents", paramLabel = "NAMES", split = ",", description = "the robot programmed by several agents "
            + "sharing its middleware (not in the thesis: its Chapter 6), each NAME the packaged agents/src/main/asl/EXPERIMENT-NAME.asl; "
            + "suspend-resume: task,energy. Lockstep, headless")
    private List<String> agentNames;

    @Option(names = "--baseline", description = "run the procedural baseline controller (the thesis' C program) instead of the agent")
    private boolean baseline;

    @Option(names = "--out", paramLabel = "DIR", description = "where the summary and the PNG go (default runs/NAME-SEED; "
            + "with another world, agent or the baseline: runs/NAME-WORLD-AGENT-baseline-SEED, each part when not the default)")
    private Path out;

    @Option(names = "--port", paramLabel = "PORT",
            description = "where the middleware listens on loopback (default: a free port)")
    private int port = 0;

    @Option(names = "--link-log", description = "also write OUT/link-log.txt: the controller's event log, a line per "
            + "control step's readings, applied command and pose (2.5-7 MB per simulated 10 minutes)")
    private boolean linkLog;

    @Option(names = "--pipeline", description = "a pipelined lockstep: the world simulates the next step while the agent "
            + "reasons, its answer applied one control step (40 ms) later; a different run from the plain lockstep's, still "
            + "a function of world, agent and seed (not the default; docs/performance.md section 18)")
    private boolean pipeline;

    @Option(names = "--remote-controller", description = "the agent side only: wait on --port (default 4444) for "
            + "`jacabot controller --lockstep` in another process, and run with it step by step (the same run as in one process)")
    private boolean remoteController;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "with --remote-controller: the link secret shared with the controller (default ~/.jacabot/link-secret)")
    private Path secretFile;

    @Mixin
    private InspectorOptions inspectorOptions = new InspectorOptions();

    @Option(names = "--break", paramLabel = "SPEC", description = "lockstep: halt after the control step where SPEC "
            + "holds, print the mind and read commands (label:NAME, +!goal, -belief(_), belief:PATTERN, failure, t=60s)")
    private List<String> breaks = new ArrayList<>();

    @Mixin
    private VerbosityOptions verbosity = new VerbosityOptions();

    @Spec
    private CommandSpec commandSpec;

    @Override
    public Integer call() throws Exception {
        ConsoleLog log = verbosity.console(commandSpec);
        PrintStream console = log.agents();
        double seconds = duration(duration);
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new UserError("--speed must be a positive number, got " + speed);
        }
        if (realTime && (lockstep || agentNames != null || remoteController || !breaks.isEmpty() || linkLog || baseline || pipeline)) {
            throw new UserError("--real-time runs one agent with the world in this process; "
                    + (lockstep ? "--lockstep" : agentNames != null ? "--agents" : remoteController ? "--remote-controller"
                    : linkLog ? "--link-log" : baseline ? "--baseline" : pipeline ? "--pipeline" : "--break")
                    + " is for lockstep runs: drop one of them");
        }
        if (pipeline && (remoteController || baseline || !breaks.isEmpty())) {
            throw new UserError("--pipeline: " + (remoteController ? "with --remote-controller the pipeline is the controller's "
                    + "option (jacabot controller --lockstep --pipeline)" : baseline ? "the baseline has no agent to pipeline"
                    : "--break halts the agent with the world a step ahead: drop one of them"));
        }
        agentOrBaseline(baseline, agent);
        if (port < 0 || port > 65535) {
            throw new UserError("--port must be in 0..65535 (0: a free port), got " + port);
        }
        Path worldFile = world != null ? Installation.locate(world) : Installation.resolve(experiment.worldFile());
        String worldName = Installation.shown(worldFile);
        WorldSpec spec;
        try {
            spec = WorldFileReader.read(worldFile);
        } catch (WorldFileException e) {
            throw new UserError(e.getMessage());
        }
        if (spec.basicTimeStep() <= 0 || spec.controlStep() <= 0 || spec.controlStep() % spec.basicTimeStep() != 0) {
            // sim-world's reader takes the number as an int: 2^40 arrives here as 0
            throw new UserError(worldName + ": $.controlStep must be a positive multiple of $.basicTimeStep ("
                    + spec.basicTimeStep() + " ms) below 2^31 ms, got " + spec.controlStep());
        }
        var missing = Landmarks.missing(experiment, spec, worldName);
        if (missing.isPresent()) { // before anything starts, agent and baseline alike
            throw new UserError(missing.get()); // a world file's error, said as the reader's are: error: file: $.path: problem
        }
        long runSeed = seed != null ? seed : spec.seed();
        spec = new WorldSpec(spec.name(), spec.arena(), spec.basicTimeStep(), spec.controlStep(), runSeed, spec.sensorNoise(),
                spec.walls(), spec.boxes(), spec.cylinders(), spec.storage(), spec.charger(), spec.robots(), spec.events());
        List<RobotAgent> robotAgents = agentNames == null
                ? List.of(new RobotAgent(RobotAgent.ALONE, agent != null ? readAgent(Installation.locate(agent))
                        : AgentSource.packaged(experiment, "agents/src/main/asl/" + experiment.id() + ".asl")))
                : RobotAgents.packaged(experiment, agentNames, agent != null ? "--agent" : baseline ? "--baseline" : null);
        AgentSource source = robotAgents.get(0).source();
        String sourceName = robotAgents.stream().map(a -> a.source().name()).collect(Collectors.joining(", "));
        var mixUps = new ArrayList<String>();
        if (!baseline) {
            for (RobotAgent a : robotAgents) {
                mixUps.addAll(ExperimentMatch.check(experiment, spec.name(), worldName, a.source().text(), a.source().name()));
            }
        } else {
            ExperimentMatch.ofWorld(spec.name()).filter(w -> w != experiment).ifPresent(w -> mixUps.add(worldName
                    + " is a world of experiment " + w.number() + " (" + w + "), not of " + experiment));
        }
        // several agents: their names stand for the agent file's in the folder (runs/suspend-resume-task-energy-13)
        Path agentPart = agentNames == null ? agent : Path.of(String.join("-", agentNames) + ".asl");
        Path outDir = out != null ? out : runFolder(experiment, world == null ? null : worldFile, agentPart, baseline, runSeed);
        prepareOut(outDir); // before the run: a run of an hour must not fail at its end on a typo
        Files.deleteIfExists(outDir.resolve(ConsoleFile.FILE)); // a run that writes none must not show an older run's
        SimWorld simWorld;
        try {
            simWorld = SimWorld.of(spec);
        } catch (RuntimeException e) {
            throw new UserError(worldName + ": this world cannot run: " + JacabotCommand.describe(e));
        }
        if (simWorld.robots().isEmpty()) {
            throw new UserError(worldName + ": the world has no robot; add one under \"robots\"");
        }
        log.info("Experiment " + experiment.number() + " (" + experiment + "): " + experiment.summary() + ".");
        mixUps.forEach(log::warn); // before the run, which goes on
        if (baseline && !experiment.hasBaseline()) {
            throw new UserError("--baseline: " + experiment + " has no procedural baseline (only the thesis' four experiments have one)");
        }
        if (baseline) {
            log.info("World " + worldName + ", seed " + runSeed + ", " + duration
                    + " of simulated time, procedural baseline, headless.");
            long t0 = System.nanoTime();
            // as BaselineRunner.execute, with the step log an agent's run writes: replayed and plotted alike
            SimWorld baselineWorld = BaselineRunner.load(worldFile, runSeed);
            var recorder = RunRecorder.attach(baselineWorld, experiment.robot());
            var controller = BaselineRunner.create(experiment, baselineWorld, runSeed, recorder::note);
            try (var steps = BaselineTap.attach(baselineWorld, outDir, experiment, BaselineRunner.CONTROLLER)) {
                controller.runFor(seconds);
            }
            report(log, recorder.summary(BaselineRunner.CONTROLLER), baselineWorld, outDir,
                    (System.nanoTime() - t0) / 1e9, -1, files(worldFile, null));
            RunPlots.writeAll(outDir, ConsoleLog.lines(log::result));
            return 0;
        }
        // a real-time run hosts one agent; several run in lockstep
        boolean viewer = !headless && !lockstep && !pipeline && agentNames == null && !GraphicsEnvironment.isHeadless();
        if (viewer || realTime) {
            log.info("World " + worldName + ", seed " + runSeed + ", real time x" + speed + (viewer
                    ? " with the viewer (close the window to stop)." : ", " + duration + ", headless (Ctrl-C to stop)."));
            return new RealTimeExperiment(experiment, speed, port, inspectorOptions, viewer).run(simWorld, worldFile, source,
                    runSeed, seconds, log, outDir);
        }
        log.info("World " + worldName + ", seed " + runSeed + ", " + duration + " of simulated time, "
                + (pipeline ? "pipelined lockstep" : "lockstep") + ", headless.");
        LockstepRun run;
        // the agents' console with its simulated times, for the inspector's console panel (the world is here only)
        // (with a remote controller the world is the other process's: the times are those of the steps it sends)
        LockstepRun[] made = new LockstepRun[1];
        // (pipelined, the world is a step ahead of the agent: the agent's clock, which is the step's time)
        ConsoleRecorder consoleFile = ConsoleRecorder.open(outDir, !remoteController && !pipeline ? simWorld::timeMs
                : () -> made[0] == null ? 0 : made[0].mas().clock().millis());
        try {
            run = new LockstepRun(simWorld, null, experiment, robotAgents, runSeed, consoleFile.tee(console)).pipeline(pipeline);
            made[0] = run;
        } catch (AslSyntaxException e) {
            throw UserError.located(e.getMessage());
        } catch (CartagoException e) {
            throw new IllegalStateException("cannot make the middleware: " + e.getMessage(), e);
        }
        if (remoteController) {
            return runWithRemoteController(run, seconds, log, consoleFile, outDir);
        }
        Robot robot = simWorld.robots().get(0);
        var inspector = inspectorOptions.start(false, "experiment " + experiment.id() + ", seed " + runSeed,
                ConsoleLog.lines(log::result), log::warn);
        var tap = RunTap.attach(run, inspector, outDir, experiment, sourceName);
        if (inspector != null) {
            inspector.console(ConsoleFile.of(outDir));
        }
        // the plots' series collected as the step log is written, not read back after the run
        var series = tap.header() == null ? null : new RunPlots.Series(tap.header());
        tap.onSteps(series);
        if (!breaks.isEmpty() || inspector != null) {
            Debugger debugger;
            try { // the page can halt the run too
                checkLabels(breaks, run.mas());
                debugger = breaks.isEmpty() ? new Debugger() : DebugConsole.start(breaks, System.in, System.out);
                // a breakpoint typed in the console or added from the page is checked as --break is
                debugger.labels(() -> labels(run.mas()));
            } catch (IllegalArgumentException e) {
                throw new UserError("--break: " + e.getMessage());
            }
            tap.debugger(inspector, debugger);
            if (inspector != null && tap.header() != null) { // what-ifs from the page, plans reloaded at a halt
                inspector.edits(PageEdits.live(inspector, outDir, tap.header(), experiment, source,
                        () -> SimWorld.of(WorldFileReader.read(worldFile)), run.mas().agent("robot"), debugger));
            }
        }
        var recorder = RunRecorder.attach(simWorld, robot.name());
        var progress = Progress.attach(simWorld, recorder, robot); // after the recorder: what it recorded at each step
        long start = System.nanoTime();
        run.onStep(data -> {
            Progress.AtStep now = progress.take(data.simTimeMs());
            consoleFile.events(now.events());
            if (now.line() != null) {
                double wall = (System.nanoTime() - start) / 1e9;
                log.info(String.format(now.line(), data.simTimeMs() / 1000.0 / Math.max(wall, 1e-6)));
            }
        });
        var done = new CountDownLatch(1);
        var terminated = new AtomicBoolean();
        ExitHook hook = ExitHook.install("experiment-shutdown", () -> {
            terminated.set(true);
            run.stop(); // SIGTERM: end at this step, write what we have (summaries first, the PNG last)
            try {
                done.await(900, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        // the link log (off unless asked for) goes to disk as it is made: a long run keeps no copy of it in memory
        try (var linkFile = linkLog ? Files.newBufferedWriter(outDir.resolve("link-log.txt"), StandardCharsets.UTF_8)
                : Writer.nullWriter()) {
            run.port(port);
            if (linkLog) {
                log.info("Link log: " + outDir.resolve("link-log.txt") + " (the controller's readings, applied commands "
                        + "and poses, a line each)");
                run.controllerLogTo(LineSink.into(linkFile));
            } else {
                run.stepLogs(false); // not formatted at all: a tenth of a run's time
            }
            LockstepCoordinator.Result result;
            try {
                result = run.runFor(seconds);
            } catch (IOException e) {
                throw new IllegalStateException(port != 0 ? "cannot listen on port " + port + " (" + e.getMessage()
                        + "); choose another with --port" : e.getMessage(), e);
            }
            double runWall = (System.nanoTime() - start) / 1e9; // the summary's factor: world, link and agent only
            linkFile.flush();
            tap.close();
            consoleFile.events(recorder.events());
            consoleFile.close(log::warn);
            if (terminated.get()) {
                log.result(String.format("Stopped by a signal at t=%.2f s; writing what there is.", simWorld.timeMs() / 1000.0));
            } else if (run.agentFailure().isPresent()) {
                result.linkLog().forEach(l -> log.detail("[link] " + l));
            } else if (result.steps() * spec.controlStep() < seconds * 1000 - spec.controlStep()) {
                log.result("The link ended early:");
                result.linkLog().forEach(l -> log.result("  " + l));
            } else {
                result.linkLog().forEach(l -> log.detail("[link] " + l));
            }
            double wall = (System.nanoTime() - start) / 1e9;
            report(log, recorder.summary("agent"), simWorld, outDir, runWall, run.cycles(), files(worldFile, sourceName));
            if (wall - runWall >= 0.05) { // the step log's writer catching up: a recording, not the run
                log.result(String.format(Locale.ROOT, "The recordings (step log, console) were finished %.1f s after the last step.", wall - runWall));
            }
            if (robotAgents.size() > 1) {
                log.result(RobotAgents.wheelSummary(run.middleware().wheelLease()));
            }
            RunPlots.writeLatency(outDir, run.reactiveSamples(), result.timings().responseSamples());
            RunPlots.writeAll(outDir, ConsoleLog.lines(log::result), series);
            if (inspector != null) {
                inspector.showPlots(outDir);
                inspectorOptions.linger(inspector, ConsoleLog.lines(log::result));
                inspector.close();
            }
            if (run.agentFailure().isPresent()) { // what the run made is written: now say why it ended
                throw new RunFailure(run.agentFailure().get());
            }
        } finally {
            done.countDown();
            hook.remove();
        }
        return 0;
    }

    /** The agent side of the two-process lockstep set-up: the world, its summary and its logs are the controller's. */
    private int runWithRemoteController(LockstepRun run, double seconds, ConsoleLog log, ConsoleRecorder consoleFile,
            Path outDir) throws Exception {
        int listen = port != 0 ? port : Protocol.DEFAULT_PORT;
        try {
            LinkSecret.useInThisProcess(secretFile != null ? LinkSecret.loadOrCreate(secretFile)
                    : LinkSecret.userDefault());
        } catch (IOException | UncheckedIOException e) {
            throw new UserError(e.getMessage() + (secretFile == null ? " (or pass --secret-file FILE)" : ""));
        }
        log.info("Waiting for `jacabot controller --lockstep --port " + listen + "` with the same world file.");
        run.onStep(data -> consoleFile.events(List.of())); // on disk at each step, for the inspector or a tail
        LockstepCoordinator.Result result;
        try {
            result = run.stepLogs(false).port(listen).remoteController(true).runFor(seconds);
        } catch (IOException e) {
            throw new IllegalStateException("cannot listen on port " + listen + " (" + e.getMessage() + "); choose another with --port", e);
        } finally {
            consoleFile.close(log::warn);
        }
        log.result(String.format("%d steps (%.1f s simulated) with the remote controller, %d reasoning cycles.", result.steps(),
                result.steps() * run.world().controlStep() / 1000.0, run.cycles()));
        log.result("Written: " + outDir.resolve(ConsoleFile.FILE) + " (the agents' console by simulated time; the world's "
                + "summary and logs are the controller's)");
        return 0;
    }

    /** {@return the agent in the file (its includes are read beside it)} @throws UserError when it cannot be read */
    static AgentSource readAgent(Path file) {
        if (!Files.isRegularFile(file)) {
            throw new UserError("--agent " + file + ": no such file");
        }
        try {
            return AgentSource.file(file);
        } catch (AccessDeniedException e) {
            throw new UserError("--agent " + file + ": permission denied; make it readable (chmod u+r)");
        } catch (MalformedInputException e) {
            throw new UserError("--agent " + file + ": not UTF-8 text");
        } catch (IOException e) {
            throw new UserError("--agent " + file + ": cannot read it (" + e.getMessage() + ")");
        }
    }

    /**
     * {@return the run's folder}: {@code runs/NAME-SEED} for the experiment's own world and agent,
     * and with the world file's name, the agent file's name or {@code baseline} before the seed when
     * they are not the defaults ({@code runs/navigation-nav7-3}, {@code runs/navigation-as-published-navigation-3}),
     * so that a run on another world or with another agent does not overwrite the default run's folder
     */
    static Path runFolder(Experiment experiment, Path world, Path agent, boolean baseline, long seed) {
        var name = new StringBuilder(experiment.id());
        if (world != null && !world.getFileName().toString().equals(experiment.id() + ".json")) {
            name.append('-').append(stem(world));
        }
        if (agent != null && !baseline) {
            String a = stem(agent);
            Path parent = agent.toAbsolutePath().normalize().getParent();
            boolean packagedDefault = a.equals(experiment.id()) && parent != null && parent.endsWith("agents/src/main/asl");
            if (!packagedDefault) {
                // a copy named like the experiment's (as-published/navigation.asl) takes its folder's name too
                name.append('-').append(a.equals(experiment.id()) && parent != null && parent.getFileName() != null
                        ? parent.getFileName() + "-" + a : a);
            }
        }
        if (baseline) {
            name.append("-baseline");
        }
        return Path.of("runs", name.append('-').append(seed).toString());
    }

    private static String stem(Path file) {
        String n = file.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return (dot > 0 ? n.substring(0, dot) : n).replaceAll("[^A-Za-z0-9._-]", "_");
    }

    /**
     * A {@code --break label:X} whose label no plan of the agents has would never halt the run:
     * refused, with the labels nearest to it.
     */
    private static void checkLabels(List<String> breaks, LocalMAS mas) {
        var labels = labels(mas);
        for (String b : breaks) {
            String why = Breakpoint.parse(b).missingLabel(labels);
            if (why != null) {
                throw new UserError("--break " + b.trim() + ": " + why);
            }
        }
    }

    /**
     * {@return the labels of the agents' plans now, or null when they cannot be read now (a plan
     * added by the running agent meanwhile): a breakpoint is then taken unchecked}
     */
    private static List<String> labels(LocalMAS mas) {
        var labels = new ArrayList<String>();
        try {
            for (String name : mas.agentNames()) {
                mas.agent(name).plans().stream().filter(p -> p.label() != null).forEach(p -> labels.add(p.label().functor()));
            }
        } catch (java.util.ConcurrentModificationException e) {
            return null;
        }
        return labels;
    }

    /** Refuses {@code --agent} with {@code --baseline}, before the agent file is looked for: the baseline would not read it. */
    static void agentOrBaseline(boolean baseline, Path agent) {
        if (baseline && agent != null) {
            throw new UserError("--agent: not with --baseline (the baseline is the procedural controller, no agent): drop one of them");
        }
    }

    /** Makes the output directory now, so a bad --out is told before the run, not after it. */
    private static void prepareOut(Path dir) {
        OutPlace.directory("--out", dir);
    }

    /** The world and agent files a run used, as the summary names them (agent null: the baseline). */
    record RunFiles(String world, String agent) {
    }

    /** {@return the files of a run on {@code world}, the world by the name a user knows it by ({@link Installation#shown})} */
    static RunFiles files(Path world, String agent) {
        return new RunFiles(Installation.shown(world), agent);
    }

    /** Writes the summary (JSON and text, naming the world and agent files), the event log and the trajectory, and prints them. */
    static void report(ConsoleLog log, RunSummary summary,
            SimWorld world, Path outDir, double wallSeconds, long cycles, RunFiles files) throws IOException {
        Files.createDirectories(outDir);
        var mapper = new ObjectMapper();
        ObjectNode json = mapper.createObjectNode().put("worldFile", files.world());
        json.put("agentFile", files.agent());
        json.setAll((ObjectNode) mapper.readTree(summary.toJson()));
        Files.writeString(outDir.resolve("summary.json"), mapper.writerWithDefaultPrettyPrinter().writeValueAsString(json) + "\n");
        String text = summary.toText();
        int first = text.indexOf('\n') + 1;
        text = text.substring(0, first) + "files: world " + files.world() + (files.agent() == null ? ", procedural baseline"
                : ", agent " + files.agent()) + "\n" + text.substring(first);
        Files.writeString(outDir.resolve("summary.txt"), text);
        Files.writeString(outDir.resolve("event-log.txt"), summary.eventLog());
        TrajectoryPlot.write(world, outDir.resolve("trajectory.png"), 800);
        log.info("");
        text.lines().forEach(log::result);
        log.result(String.format("%.0f s simulated in %.1f s (%.0fx real time)%s.", summary.duration(), wallSeconds,
                summary.duration() / Math.max(wallSeconds, 1e-9), cycles >= 0 ? ", " + cycles + " reasoning cycles" : ""));
        log.result("Written: " + outDir.resolve("summary.json") + ", summary.txt, event-log.txt, trajectory.png"
                + (Files.exists(outDir.resolve(StepLog.FILE)) ? ", " + StepLog.FILE : "")
                + (Files.exists(outDir.resolve(ConsoleFile.FILE)) ? ", " + ConsoleFile.FILE : ""));
    }

    /** {@return the seconds of a --duration} @throws UserError when it is not one, or no time at all */
    static double duration(String text) {
        double seconds;
        try {
            seconds = parseDuration(text);
        } catch (IllegalArgumentException e) {
            throw new UserError("--duration: " + e.getMessage());
        }
        if (!(seconds > 0)) { // a run of no time has no step to write, and a run waiting for its end would wait for ever
            throw new UserError("--duration: must be more than 0, got '" + text + "' (examples: 90s, 10m, 1h)");
        }
        return seconds;
    }

    static double parseDuration(String text) {
        var m = Pattern.compile("(\\d+(?:\\.\\d+)?)\\s*(ms|s|m|min|h)?").matcher(text.trim());
        if (!m.matches()) {
            throw new IllegalArgumentException("bad duration '" + text + "' (examples: 90s, 10m, 1h)");
        }
        double v = Double.parseDouble(m.group(1));
        String unit = m.group(2) == null ? "s" : m.group(2);
        switch (unit) {
            case "ms": return v / 1000;
            case "m":
            case "min": return v * 60;
            case "h": return v * 3600;
            default: return v;
        }
    }

    static final class ExperimentConverter implements ITypeConverter<Experiment> {
        @Override
        public Experiment convert(String value) {
            return Experiment.parse(value).orElseThrow(() -> new TypeConversionException("unknown experiment '" + value
                    + "' (expected one of obstacle-avoidance, object-picking, navigation, suspend-resume, tidy-up, 1-5; or team-delivery)"));
        }
    }
}
