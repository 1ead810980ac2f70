package jacabot.scenario;

import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepCoordinator;
import jacabot.app.run.LockstepRun;
import jacabot.app.run.RobotAgent;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.engine.ObjectKind;
import jacabot.sim.engine.ObjectState;
import jacabot.sim.geom.Pose;
import jacabot.sim.io.WorldFileReader;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.AreaSpec;
import jacabot.sim.world.WorldSpec;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.BiConsumer;
import java.util.function.UnaryOperator;

/**
 * One lockstep run of an experiment with the agent in the loop, and what the scenario tests read
 * from it: the ground truth of the world sampled every control step (pose, battery, carried
 * cylinder), the deliveries (a cylinder released with its centre inside the storage radius), the
 * agent's console lines with the simulated time they appeared at, and the coordinator's result.
 */
final class ScenarioRun {
    /** One console line and the simulated time (ms) of the control step it was printed in. */
    record Line(long timeMs, String text) {
    }

    /** One control step's ground truth. */
    record Sample(long timeMs, Pose pose, double battery, String carried) {
    }

    /** A cylinder leaving the gripper: where it was at the end of that step. */
    record Release(long timeMs, String cylinder, double x, double z, boolean inStorage) {
    }

    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));
    static final boolean ECHO = Boolean.getBoolean("jacabot.scenario.echo");

    final Experiment experiment;
    final long seed;
    final SimWorld world;
    final Robot robot;
    final List<Line> lines = new ArrayList<>();
    final List<Sample> samples = new ArrayList<>();
    final List<Release> releases = new ArrayList<>();
    LockstepCoordinator.Result result;
    /** The lockstep run (its agents, its middleware artifact). */
    LockstepRun lockstep;
    private long nowMs;

    private ScenarioRun(Experiment experiment, long seed, SimWorld world) {
        this.experiment = experiment;
        this.seed = seed;
        this.world = world;
        this.robot = world.robots().get(0);
    }

    /** Runs {@code experiment} in its world file under {@code seed}. */
    static ScenarioRun run(Experiment experiment, long seed, boolean noise, double seconds) throws Exception {
        return run(experiment, seed, noise, seconds, UnaryOperator.identity(), (t, r) -> {
        });
    }

    /**
     * @param edit changes the world before it is built
     * @param eachStep called after every control step with its time (ms), e.g. to move objects
     */
    static ScenarioRun run(Experiment experiment, long seed, boolean noise, double seconds, UnaryOperator<WorldSpec> edit,
            BiConsumer<Long, ScenarioRun> eachStep) throws Exception {
        return run(experiment, experiment.agentResource(), seed, noise, seconds, edit, eachStep);
    }

    /** Runs the agent as the thesis published it ({@code agents/src/main/asl/as-published/}, without our recovery plans). */
    static ScenarioRun runPublished(Experiment experiment, long seed, boolean noise, double seconds) throws Exception {
        return runPublished(experiment, seed, noise, seconds, UnaryOperator.identity(), (t, r) -> {
        });
    }

    static ScenarioRun runPublished(Experiment experiment, long seed, boolean noise, double seconds, UnaryOperator<WorldSpec> edit,
            BiConsumer<Long, ScenarioRun> eachStep) throws Exception {
        String published = experiment.agentResource().replaceFirst("/([^/]+)$", "/as-published/$1");
        return run(experiment, published, seed, noise, seconds, edit, eachStep);
    }

    private static ScenarioRun run(Experiment experiment, String agentResource, long seed, boolean noise, double seconds,
            UnaryOperator<WorldSpec> edit, BiConsumer<Long, ScenarioRun> eachStep) throws Exception {
        var agent = new RobotAgent(RobotAgent.ALONE, AgentSource.resource(agentResource, experiment.id() + ".asl"));
        return run(experiment, List.of(agent), seed, noise, seconds, edit, eachStep);
    }

    /**
     * Runs {@code experiment} with the robot programmed by several agents sharing its middleware
     * (e.g. a task agent and an energy agent); {@link #lockstep} is the run, for its middleware.
     */
    static ScenarioRun run(Experiment experiment, List<RobotAgent> agents, long seed, boolean noise, double seconds,
            UnaryOperator<WorldSpec> edit, BiConsumer<Long, ScenarioRun> eachStep) throws Exception {
        WorldSpec s = WorldFileReader.read(ROOT.resolve(experiment.worldFile()));
        s = new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), seed, noise, s.walls(), s.boxes(),
                s.cylinders(), s.storage(), s.charger(), s.robots(), s.events());
        s = edit.apply(s);
        ScenarioRun run = new ScenarioRun(experiment, seed, SimWorld.of(s));
        var lockstep = new LockstepRun(run.world, null, experiment, agents, seed,
                new PrintStream(run.new LineSink(), true, StandardCharsets.UTF_8));
        run.lockstep = lockstep;
        AreaSpec storage = s.storage();
        lockstep.onStep(data -> {
            run.nowMs = data.simTimeMs();
            run.sample(storage);
            eachStep.accept(data.simTimeMs(), run);
        });
        run.result = lockstep.runFor(seconds);
        return run;
    }

    private void sample(AreaSpec storage) {
        synchronized (world) {
            String carried = robot.hasGripper() ? world.supervisor().carried(robot.name()) : null;
            double battery = robot.hasBattery() ? robot.getBattery().energy() : Double.NaN;
            if (!samples.isEmpty()) {
                String before = samples.get(samples.size() - 1).carried();
                if (before != null && !before.equals(carried)) {
                    Pose p = world.supervisor().pose(before);
                    boolean in = storage != null && Math.hypot(p.x() - storage.x(), p.z() - storage.z()) < storage.radius();
                    releases.add(new Release(nowMs, before, p.x(), p.z(), in));
                }
            }
            samples.add(new Sample(nowMs, robot.pose(), battery, carried));
        }
    }

    // ---- what the tests read ---------------------------------------------------------------------

    /** {@return the console lines containing {@code text}} */
    /** {@return the first sample time from {@code fromMs} at which the heading changed by over 3° since then, or -1} */
    long firstTurn(long fromMs) {
        Double h0 = null;
        for (Sample s : samples) {
            if (s.timeMs() < fromMs) {
                continue;
            }
            if (h0 == null) {
                h0 = s.pose().heading();
            } else {
                double d = Math.abs(s.pose().heading() - h0) % 360;
                if (Math.min(d, 360 - d) > 3) {
                    return s.timeMs();
                }
            }
        }
        return -1;
    }

    List<Line> linesWith(String text) {
        List<Line> out = new ArrayList<>();
        for (Line l : lines) {
            if (l.text().contains(text)) {
                out.add(l);
            }
        }
        return out;
    }

    /** {@return the time (ms) of the first console line containing {@code text} after {@code fromMs}, or -1} */
    long firstLine(String text, long fromMs) {
        for (Line l : lines) {
            if (l.timeMs() >= fromMs && l.text().contains(text)) {
                return l.timeMs();
            }
        }
        return -1;
    }

    /** {@return the number of cylinders released inside the storage area} */
    long deliveries() {
        return releases.stream().filter(Release::inStorage).count();
    }

    /** {@return the share of the arena's cells (of {@code cell} metres) the robot's centre visited} */
    double coverage(double cell) {
        double w = world.spec().arena().width();
        double d = world.spec().arena().depth();
        Set<Long> seen = new HashSet<>();
        for (Pose p : robot.trajectory()) {
            long i = (long) Math.floor((p.x() + w / 2) / cell);
            long j = (long) Math.floor((p.z() + d / 2) / cell);
            seen.add(i * 10_000 + j);
        }
        return seen.size() / (Math.ceil(w / cell) * Math.ceil(d / cell));
    }

    /** {@return the distance (m) the robot's centre travelled between {@code fromMs} and {@code toMs}} */
    double travelled(long fromMs, long toMs) {
        double sum = 0;
        Sample prev = null;
        for (Sample s : samples) {
            if (s.timeMs() >= fromMs && s.timeMs() <= toMs) {
                if (prev != null) {
                    sum += Math.hypot(s.pose().x() - prev.pose().x(), s.pose().z() - prev.pose().z());
                }
                prev = s;
            }
        }
        return sum;
    }

    double minBattery() {
        return samples.stream().mapToDouble(Sample::battery).min().orElse(Double.NaN);
    }

    /** {@return the sample at or just after {@code timeMs}} */
    Sample at(long timeMs) {
        for (Sample s : samples) {
            if (s.timeMs() >= timeMs) {
                return s;
            }
        }
        return samples.get(samples.size() - 1);
    }

    /** {@return the cylinders' current states} */
    List<ObjectState> cylinders() {
        synchronized (world) {
            return world.supervisor().objects().stream().filter(o -> o.kind() == ObjectKind.CYLINDER).toList();
        }
    }

    /** {@return a one-line account of the run, for failure messages} */
    String summary() {
        return String.format("%s seed %d: %.0f s, coverage %.2f, contact %.1f s, deliveries %d, releases %s, min battery %.0f J,"
                + " last lines %s", experiment, seed, nowMs / 1000.0, coverage(0.05), robot.contactTime(), deliveries(), releases,
                minBattery(), lines.subList(Math.max(0, lines.size() - 8), lines.size()));
    }

    /** Collects console output as lines stamped with the simulated time. */
    private final class LineSink extends OutputStream {
        private final ByteArrayOutputStream buf = new ByteArrayOutputStream();

        @Override
        public synchronized void write(int b) throws IOException {
            if (b == '\n') {
                String text = buf.toString(StandardCharsets.UTF_8);
                buf.reset();
                lines.add(new Line(nowMs, text));
                if (ECHO) {
                    System.out.printf("%8.2f %s%n", nowMs / 1000.0, text);
                }
            } else {
                buf.write(b);
            }
        }
    }
}
