package jacabot.app.scenario;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.app.Installation;
import jacabot.app.plot.RunPlots;
import jacabot.app.plot.TrajectoryPlot;
import jacabot.app.replay.RunTap;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.cartago.CartagoException;
import jacabot.robot.Experiment;
import jacabot.robot.run.RunRecorder;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Objects;

/**
 * Scenario tests for your own agents and worlds: one experiment of the thesis' Chapter 4 run in
 * lockstep (deterministic under a seed, as fast as the machine allows), ending with the run's
 * summary and event log.
 *
 * <pre>{@code
 * ScenarioResult r = Scenario.of("navigation")
 *         .agent(Path.of("my-navigation.asl"))     // default: the experiment's packaged agent
 *         .world(Path.of("my-world.json"))          // default: worlds/navigation.json
 *         .seed(3)                                  // default: the world file's seed
 *         .duration(Duration.ofSeconds(90))         // simulated time, default 60 s
 *         .run();
 * assertTrue(r.summary().picks() >= 1, r.eventLog());
 * }</pre>
 *
 * Paths are relative to the current folder. The experiment names the middleware artifact the
 * agent works with ({@code obstacle-avoidance}, {@code object-picking}, {@code navigation},
 * {@code suspend-resume}, or 1-4).
 */
public final class Scenario {
    private final Experiment experiment;
    private Path agent;
    private Path world;
    private Long seed;
    private Duration duration = Duration.ofSeconds(60);
    private Path out;

    private Scenario(Experiment experiment) {
        this.experiment = experiment;
    }

    /** @throws IllegalArgumentException for an unknown experiment */
    public static Scenario of(String experiment) {
        return new Scenario(Experiment.parse(experiment).orElseThrow(() -> new IllegalArgumentException(
                "unknown experiment '" + experiment + "' (expected obstacle-avoidance, object-picking, navigation, suspend-resume, tidy-up)")));
    }

    /** The agent's .asl file (default: the experiment's own agent). */
    public Scenario agent(Path file) {
        this.agent = Objects.requireNonNull(file);
        return this;
    }

    /** The world file (default: the experiment's world). */
    public Scenario world(Path file) {
        this.world = Objects.requireNonNull(file);
        return this;
    }

    /** The seed of the world's noise and the agent's random numbers (default: the world file's). */
    public Scenario seed(long value) {
        this.seed = value;
        return this;
    }

    /** How much simulated time to run. */
    public Scenario duration(Duration simulated) {
        if (simulated.isNegative() || simulated.isZero()) {
            throw new IllegalArgumentException("the duration must be positive, got " + simulated);
        }
        this.duration = simulated;
        return this;
    }

    /** Also writes the run's folder there, as {@code jacabot experiment} does (summary, step log, plots). */
    public Scenario out(Path dir) {
        this.out = dir;
        return this;
    }

    /**
     * Runs the scenario.
     *
     * @throws ScenarioException when the world or the agent cannot be read (with file:line:col)
     */
    public ScenarioResult run() throws IOException, InterruptedException {
        Path worldFile = world != null ? world : Installation.resolve(experiment.worldFile());
        WorldSpec s;
        try {
            s = WorldFileReader.read(worldFile);
        } catch (WorldFileException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
        long runSeed = seed != null ? seed : s.seed();
        s = new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), runSeed, s.sensorNoise(), s.walls(),
                s.boxes(), s.cylinders(), s.storage(), s.charger(), s.robots(), s.events());
        AgentSource source;
        if (agent != null) {
            if (!Files.isRegularFile(agent)) {
                throw new ScenarioException(agent + ": no such file", null);
            }
            source = AgentSource.file(agent);
        } else {
            source = AgentSource.packaged(experiment);
        }
        String sourceName = source.name();
        var console = new ByteArrayOutputStream();
        SimWorld simWorld = SimWorld.of(s);
        LockstepRun run;
        try {
            run = new LockstepRun(simWorld, null, experiment, source, runSeed,
                    new PrintStream(console, true, StandardCharsets.UTF_8)).stepLogs(false);
        } catch (AslSyntaxException e) {
            throw new ScenarioException(e.getMessage(), e);
        } catch (CartagoException e) {
            throw new ScenarioException("cannot make the middleware: " + e.getMessage(), e);
        }
        var recorder = RunRecorder.attach(simWorld, simWorld.robots().get(0).name());
        try (run; RunTap tap = out == null ? null : RunTap.attach(run, null, out, experiment, sourceName)) {
            run.runFor(duration.toMillis() / 1000.0);
        }
        var summary = recorder.summary("agent");
        if (out != null) {
            summary.writeJson(out.resolve("summary.json"));
            Files.writeString(out.resolve("summary.txt"), summary.toText());
            Files.writeString(out.resolve("event-log.txt"), summary.eventLog());
            TrajectoryPlot.write(simWorld, out.resolve("trajectory.png"), 800);
            RunPlots.writeAll(out, new PrintStream(OutputStream.nullOutputStream()));
        }
        return new ScenarioResult(summary, List.of(console.toString(StandardCharsets.UTF_8).split("\\R")), run.agentFailure());
    }
}
