package jacabot.app.sweep;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.app.run.AgentSource;
import jacabot.app.run.TeamLockstepRun;
import jacabot.app.run.TeamWatch;
import jacabot.cartago.CartagoException;
import jacabot.robot.baseline.TeamBaseline;
import jacabot.robot.run.RunRecorder;
import jacabot.robot.run.RunSummary;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.WorldSpec;
import java.io.Closeable;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * One run of team-delivery (thesis Chapter 6): a team of agents in lockstep ({@link TeamLockstepRun})
 * or the procedural team without coordination ({@link TeamBaseline}), each robot recorded from
 * ground truth, and the run judged by {@link SuccessCriteria#judgeTeam}.
 */
public final class TeamDeliveryRun {
    /** The agents' controller name in the summaries. */
    public static final String AGENTS = "team agents";

    private TeamDeliveryRun() {
    }

    /**
     * What a team run leaves.
     *
     * @param robots        every robot's summary, in the world file's order
     * @param claims        claims made on the task board (0 for the baseline, which has none)
     * @param chargerWaits  how many times a robot waited at the charger behind another (TeamWatch)
     * @param linkLogs      every robot's controller event log: a line per reading, applied command and pose
     *                      (agents only, when kept)
     * @param agentFailure  the first agent that failed at its job, and why
     * @param departures    the agents that left the team during the run (died), and when
     */
    public record Outcome(boolean baseline, long seed, List<RunSummary> robots, int claims, int chargerWaits,
                          SuccessCriteria.TeamFigures figures, SuccessCriteria.Verdict verdict,
                          Map<String, List<String>> linkLogs, Optional<String> agentFailure, long cycles,
                          List<String> departures) {
        /** {@return the team's deliveries} */
        public int deliveries() {
            return figures.deliveries();
        }
    }

    /** {@return the spec with the run's seed} */
    public static WorldSpec withSeed(WorldSpec s, long seed) {
        return new WorldSpec(s.name(), s.arena(), s.basicTimeStep(), s.controlStep(), seed, s.sensorNoise(), s.walls(),
                s.boxes(), s.cylinders(), s.storage(), s.charger(), s.robots(), s.events());
    }

    /**
     * Runs the team of agents for {@code seconds}.
     *
     * @param onStep called after each control step with the simulated time in ms (progress), or null
     */
    public static Outcome agents(WorldSpec spec, AgentSource agent, long seed, double seconds, PrintStream console,
            boolean stepLogs, Consumer<Long> onStep) throws AslSyntaxException, CartagoException, IOException, InterruptedException {
        return agents(spec, agent, seed, seconds, console, stepLogs, onStep, null);
    }

    /** What watches a team's run (its robots' step logs, the inspector): attached before it runs, closed after. */
    @FunctionalInterface
    public interface Tap {
        Closeable attach(TeamLockstepRun run) throws IOException;
    }

    /**
     * As {@link #agents(WorldSpec, AgentSource, long, double, PrintStream, boolean, Consumer)}, watched by {@code tap}.
     *
     * @param tap attached before the run and closed after it, or null
     * @throws IOException when the tap cannot write
     */
    public static Outcome agents(WorldSpec spec, AgentSource agent, long seed, double seconds, PrintStream console,
            boolean stepLogs, Consumer<Long> onStep, Tap tap)
            throws AslSyntaxException, CartagoException, IOException, InterruptedException {
        SimWorld world = SimWorld.of(withSeed(spec, seed));
        List<RunRecorder> recorders = attach(world);
        try (TeamLockstepRun run = new TeamLockstepRun(world, agent, seed, console);
                Closeable watching = tap == null ? null : tap.attach(run)) {
            run.stepLogs(stepLogs);
            if (onStep != null) {
                run.onStep(onStep);
            }
            run.runFor(seconds);
            Map<String, List<String>> logs = new LinkedHashMap<>();
            for (String r : run.robots()) {
                logs.put(r, run.controllerLog(r));
            }
            List<RunSummary> summaries = summaries(recorders, AGENTS);
            TeamWatch w = run.watch();
            var figures = figures(world, summaries, w.doubleClaims(), w.longestChargerWait());
            return new Outcome(false, seed, summaries, w.claims(), w.chargerWaits(), figures,
                    SuccessCriteria.judgeTeam(figures), logs, run.agentFailure(), run.cycles(), run.departures());
        }
    }

    /** Runs the procedural team (N copies of experiment 4's baseline, no coordination) for {@code seconds}. */
    public static Outcome baseline(WorldSpec spec, long seed, double seconds) throws InterruptedException {
        TeamBaseline.TeamRun run = TeamBaseline.run(SimWorld.of(withSeed(spec, seed)), seed, seconds);
        var figures = figures(run.world(), run.summaries(), 0, 0);
        return new Outcome(true, seed, run.summaries(), 0, 0, figures, SuccessCriteria.judgeTeam(figures), Map.of(),
                Optional.empty(), 0, List.of());
    }

    /** {@return a recorder of ground truth per robot of the world, in its order} */
    public static List<RunRecorder> attach(SimWorld world) {
        List<RunRecorder> out = new ArrayList<>();
        for (Robot r : world.robots()) {
            out.add(RunRecorder.attach(world, r.name()));
        }
        return out;
    }

    /** {@return every recorder's summary, naming {@code controller}} */
    public static List<RunSummary> summaries(List<RunRecorder> recorders, String controller) {
        List<RunSummary> out = new ArrayList<>();
        for (RunRecorder r : recorders) {
            out.add(r.summary(controller));
        }
        return out;
    }

    private static SuccessCriteria.TeamFigures figures(SimWorld world, List<RunSummary> robots, int doubleClaims,
            double longestWait) {
        double duration = robots.isEmpty() ? 0 : robots.get(0).duration();
        int deliveries = robots.stream().mapToInt(RunSummary::deliveries).sum();
        List<Double> contacts = robots.stream().map(RunSummary::contactTime).toList();
        // every robot of the world is on the team, in the world file's order, as the summaries
        List<Double> robotContacts = world.robots().stream().map(Robot::robotContactTime).toList();
        int emptied = (int) robots.stream().filter(RunSummary::batteryEmptied).count();
        return new SuccessCriteria.TeamFigures(duration, world.spec().cylinders().size(), deliveries, contacts, robotContacts,
                emptied, doubleClaims, longestWait);
    }
}
