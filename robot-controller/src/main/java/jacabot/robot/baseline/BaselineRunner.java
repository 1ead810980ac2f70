package jacabot.robot.baseline;
import jacabot.robot.Experiment;

import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileException;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.world.WorldSpec;
import java.nio.file.Path;
import java.util.function.Consumer;

/**
 * Runs a procedural baseline headless, as fast as the simulator goes, in lockstep: load the world
 * with the run's seed (sensor noise and random motion), attach a {@link RunRecorder}, let the
 * controller poll and step for the given simulated time, and summarise.
 */
public final class BaselineRunner {
    /** The {@code controller} of the summaries. */
    public static final String CONTROLLER = "baseline";

    private BaselineRunner() {
    }

    /** A finished run: the world as it ended, its recorder, the controller and the summary. */
    public record BaselineRun(SimWorld world, RunRecorder recorder, BaselineController controller, RunSummary summary) {
    }

    /** {@return the summary of a baseline run} @throws WorldFileException when the world file is bad */
    public static RunSummary run(Path worldFile, Experiment experiment, long seed, double simulatedSeconds)
            throws WorldFileException {
        return execute(worldFile, experiment, seed, simulatedSeconds).summary();
    }

    /** {@return a finished baseline run, for callers that need more than the summary} */
    public static BaselineRun execute(Path worldFile, Experiment experiment, long seed, double simulatedSeconds)
            throws WorldFileException {
        SimWorld world = load(worldFile, seed);
        RunRecorder recorder = RunRecorder.attach(world, experiment.robot());
        BaselineController controller = create(experiment, world, seed, recorder::note);
        controller.runFor(simulatedSeconds);
        return new BaselineRun(world, recorder, controller, recorder.summary(CONTROLLER));
    }

    /** {@return the world of a file, with its seed replaced by {@code seed}} */
    public static SimWorld load(Path worldFile, long seed) throws WorldFileException {
        WorldSpec s = WorldFileReader.read(worldFile);
        return SimWorld.of(new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), seed, s.sensorNoise(),
                s.walls(), s.boxes(), s.cylinders(), s.storage(), s.charger(), s.robots(), s.events()));
    }

    /**
     * {@return the equal-capability baseline of an experiment: the thesis-style program with the
     * default agent's strategies ({@link EqualCapabilities}, {@link EqualObstacleAvoidanceBaseline})}
     */
    public static BaselineController createEqual(Experiment experiment, SimWorld world, long seed, Consumer<String> console) {
        if (experiment == Experiment.OBSTACLE_AVOIDANCE) {
            return new EqualObstacleAvoidanceBaseline(world, experiment.robot(), seed, console);
        }
        return ((ObjectPickingBaseline) create(experiment, world, seed, console)).withEqualCapabilities();
    }

    /** {@return the baseline controller of an experiment, driving the experiment's robot in {@code world}} */
    public static BaselineController create(Experiment experiment, SimWorld world, long seed, Consumer<String> console) {
        String robot = experiment.robot();
        switch (experiment) {
            case OBSTACLE_AVOIDANCE:
                return new ObstacleAvoidanceBaseline(world, robot, seed, console);
            case OBJECT_PICKING:
                return new ObjectPickingBaseline(world, robot, seed, console);
            case NAVIGATION:
                return new NavigationBaseline(world, robot, seed, console);
            case SUSPEND_RESUME:
                return new SuspendResumeBaseline(world, robot, seed, console);
            default:
                throw new IllegalArgumentException("no baseline for " + experiment);
        }
    }
}
