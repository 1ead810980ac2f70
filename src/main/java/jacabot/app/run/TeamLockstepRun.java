package jacabot.app.run;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.CartagoException;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.CAgentArch;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.SuspendResumeMiddleware;
import jacabot.experiments.link.LinkConfig;
import jacabot.experiments.link.StepData;
import jacabot.experiments.team.ChargerQueue;
import jacabot.experiments.team.SearchMap;
import jacabot.experiments.team.TaskBoard;
import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.RobotController;
import jacabot.robot.TeamLockstep;
import jacabot.robot.link.Command;
import jacabot.sim.SimWorld;
import jacabot.sim.robot.Robot;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * A team of robots in one world, one agent per robot, in lockstep in one process (thesis Chapter 6,
 * multi-robot systems). Every robot has its controller and its middleware artifact
 * ({@code middleware_<robot>}) joined by in-memory frames (as {@link LockstepCoordinator#inMemory});
 * its agent is named as the robot. The agents share one stepped workspace with the team's task
 * board ({@code board}), charger queue ({@code charger}) and search map ({@code search}).
 *
 * <p>Each control step: every robot's readings are sampled, then sent and delivered to its
 * middleware, in the world file's order; only then do the agents reason, together, until quiescent
 * (the barrier); then every robot's commands are answered and applied in the world file's order,
 * and the world advances one step. So a run is a pure function of the world file and the seed: the
 * same world and seed give every robot the same event log, to the byte. Its clock, workspace and
 * agents are the {@link SteppedPlatform}'s.
 */
public final class TeamLockstepRun extends SteppedPlatform {
    /** The artifacts every agent of the team shares. */
    public static final String BOARD = "board", CHARGER = "charger", SEARCH = "search";
    /** Two claims' places closer than this are one cylinder on the board, metres (rough camera estimates). */
    public static final double CLAIM_RADIUS = 0.2;

    private final List<TeamMember> members = new ArrayList<>();
    private final TaskBoard board;
    private final ChargerQueue charger;
    private final TeamWatch watch;
    private final List<String> linkLog = new ArrayList<>();
    private boolean stepLogs = true;
    /** The first run's end is the team's task's ({@link WorldBeliefs#tellTeamTaskEnd}). */
    private boolean taskEndTold;
    /** Two processes: the controllers are another process's; robot i's link listens on {@code port + i} (0: free ports). */
    private boolean remote;
    private int port;
    private volatile TeamRemoteLinks remoteLinks;
    private final Object arrivals = new Object();
    private final List<String> departures = new ArrayList<>();
    private volatile boolean stopRequested;
    private RuntimeException failure;
    private Consumer<Long> onStep = t -> {
    };
    private RobotStepListener onAnswer = (robot, data, commands) -> {
    };

    /** What a robot's link delivered in a control step and what its agent answered. */
    @FunctionalInterface
    public interface RobotStepListener {
        void afterStep(String robot, StepData data, List<Command> commands);
    }

    /**
     * @param world every robot of it is a member of the team, in the file's order
     * @param agent the program of every robot's agent
     */
    public TeamLockstepRun(SimWorld world, AgentSource agent, long seed, PrintStream console)
            throws AslSyntaxException, CartagoException {
        super(world, seed, console);
        Workspace workspace = workspace();
        LocalMAS mas = mas();
        mas.onAgentDied(this::agentDied);
        ArtifactId boardId = workspace.createArtifact(BOARD, TaskBoard.class.getName(), CLAIM_RADIUS);
        board = workspace.artifactObject(boardId, TaskBoard.class).orElseThrow();
        ArtifactId chargerId = workspace.createArtifact(CHARGER, ChargerQueue.class.getName());
        charger = workspace.artifactObject(chargerId, ChargerQueue.class).orElseThrow();
        workspace.createArtifact(SEARCH, SearchMap.class.getName());
        AslParser parser = agent.parser();
        for (Robot robot : world.robots()) {
            String name = robot.name();
            // made before the agents start, so that each one's !init finds its own (thesis Chapter 4 §5)
            ArtifactId id = workspace.createArtifact("middleware_" + name, SuspendResumeMiddleware.class.getName(), 0, "lockstep");
            MiddlewareArtifact middleware = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
            AgentProgram program = WorldBeliefs.inject(agent.parse(parser), world.spec(), Experiment.SUSPEND_RESUME);
            List<Literal> goals = program.goals();
            FailureWatch failures = new FailureWatch(goals);
            watch(name, failures);
            Agent agentOfRobot = mas.createAgent(name, program, parser, CAgentArch::new);
            agentOfRobot.setPlanListener((event, plan) -> failures.planSelected(event, clock().nowMillis()));
            agentOfRobot.setUnhandledFailureListener((failure, root) -> failures.failureUnhandled(failure, root, clock().nowMillis()));
            members.add(new TeamMember(name, id, middleware, failures, goals, this::arrived));
        }
        watch = new TeamWatch(world, board, charger, members.stream().map(TeamMember::robot).toList());
    }

    /** Whether every robot's event log keeps a line per step (readings, commands, pose); on by default. */
    public TeamLockstepRun stepLogs(boolean keep) {
        this.stepLogs = keep;
        return this;
    }

    /** Called after each control step with the simulated time (progress lines). */
    public void onStep(Consumer<Long> listener) {
        this.onStep = listener;
    }

    /**
     * Called for each robot after each control step, in the world file's order, with its readings
     * and the commands going to it: the agents are idle, the world not yet stepped (step logs, the
     * inspector). Only reads, so the run is the same with or without it.
     */
    public void onAnswer(RobotStepListener listener) {
        this.onAnswer = listener;
    }

    /** {@return the team's robots, in the world file's order} */
    public List<String> robots() {
        return members.stream().map(TeamMember::robot).toList();
    }

    /** {@return what the run's watch saw: claims, double claims, charger waits} */
    public TeamWatch watch() {
        return watch;
    }

    /** {@return the team's task board (read it between two steps, e.g. in {@link #onStep})} */
    public TaskBoard board() {
        return board;
    }

    /** {@return the team's charger queue (read it between two steps)} */
    public ChargerQueue charger() {
        return charger;
    }

    /**
     * {@return robot {@code robot}'s event log: its controller's lines (readings, applied commands and
     * poses), a line {@code --}, its agent side's (a step's readings and the commands answered)}
     */
    public List<String> eventLog(String robot) {
        return member(robot).eventLog();
    }

    /** {@return robot {@code robot}'s controller's lines (empty when the controllers are in another process)} */
    public List<String> controllerLog(String robot) {
        return List.copyOf(member(robot).controllerLog());
    }

    /** {@return robot {@code robot}'s agent side's lines, one per step answered} */
    public List<String> agentLog(String robot) {
        return List.copyOf(member(robot).agentLog());
    }

    private TeamMember member(String robot) {
        return members.stream().filter(m -> m.robot().equals(robot)).findFirst().orElseThrow();
    }

    /** {@return the first agent that failed at its job and why, e.g. "khepera2: no plan for !start"} */
    public Optional<String> agentFailure() {
        for (TeamMember m : members) {
            Optional<String> v = m.failures().verdict();
            if (v.isPresent()) {
                return Optional.of(m.robot() + ": " + v.get());
            }
        }
        return Optional.empty();
    }

    /** Ends a run in progress after the current step. */
    public void stop() {
        stopRequested = true;
    }

    @Override
    public void close() {
        members.forEach(TeamMember::closeLink);
        super.close();
    }

    // ---- two processes: the controllers in another ({@code jacabot controller --lockstep --world FILE}) ----

    /**
     * The controllers are another process's ({@code jacabot controller --lockstep} with the same
     * world file and team): robot i's link listens on {@link #port} + i, and each step is answered
     * once every robot's step has come (the barrier stays here), so the run is the one-process run.
     * The world here only gives the spec; it is not stepped, and {@link #watch} counts nothing.
     */
    public TeamLockstepRun remoteController(boolean on) {
        this.remote = on;
        return this;
    }

    /** With {@link #remoteController}: robot i's link listens on {@code basePort + i} (0: each on a free port). */
    public TeamLockstepRun port(int basePort) {
        this.port = basePort;
        return this;
    }

    /** {@return with {@link #remoteController}, the ports listened on in the robots' order, once they are (empty before)} */
    public List<Integer> listeningPorts() {
        TeamRemoteLinks l = remoteLinks;
        return l == null ? List.of() : l.ports();
    }

    /** {@return the agents that left the team during the run and why, e.g. "khepera2 at t=12.3 s: its reasoning threw ..."} */
    public List<String> departures() {
        return List.copyOf(departures);
    }

    /** The agents' half with the controllers in another process, until {@code seconds} of steps or their goodbye. */
    private void runRemote(double seconds) throws IOException, InterruptedException {
        try (TeamRemoteLinks links = TeamRemoteLinks.open(members, port, linkLog::add)) {
            remoteLinks = links;
            long endAt = Math.round(seconds * 1000);
            int controlStep = world().controlStep();
            while (!stopRequested && failure == null) {
                long now = links.awaitSteps(arrivals, () -> stopRequested);
                if (now < 0) {
                    break; // every controller said goodbye, or stop()
                }
                agentsTurnOrFail(now);
                afterStep(now);
                if (now + controlStep >= endAt) {
                    links.awaitGoodbyes(arrivals); // the answer is on its way: closing now could cut it off
                    break;
                }
            }
        } finally {
            remoteLinks = null;
        }
        if (failure != null) {
            throw failure;
        }
    }

    private void arrived() {
        synchronized (arrivals) {
            arrivals.notifyAll();
        }
    }

    // ---- an agent that dies leaves the team ----

    /** An agent's reasoning threw (on the run's thread, inside the agents' turn): it is out of the system. */
    private void agentDied(String agent, Throwable why) {
        mas().console("[" + agent + "] *** the agent died: " + why);
    }

    /**
     * After the agents' turn: an agent no longer in the system (it died, or {@code .kill_agent})
     * leaves the workspace, so the board frees its claims and the charger queue its place
     * ({@code agentLeft}), and its robot's link is closed, so its controller's fail-safe stops it.
     */
    private void departuresAfterReasoning(long now) {
        LocalMAS mas = mas();
        Workspace workspace = workspace();
        for (TeamMember m : members) {
            if (m.left() != null || (mas.agent(m.robot()) != null && !mas.agent(m.robot()).isStopped())) {
                continue;
            }
            for (AgentId a : workspace.agents()) {
                if (a.name().equals(m.robot())) {
                    workspace.leave(a);
                }
            }
            String why = String.format(Locale.ROOT, "%s at t=%.2f s: its agent is gone", m.robot(), now / 1000.0);
            departures.add(why);
            m.agentLeft(why);
        }
    }

    /**
     * Tells every agent that the team's task ends {@code seconds} from now ({@code taskEnd}): for a
     * run watched over less than its task (a scenario test of a task's first minutes). Without it
     * the first {@link #runFor}'s end is the task's.
     *
     * @throws IllegalStateException when the task's end was told already
     */
    public void tellTaskEnd(double seconds) {
        if (taskEndTold) {
            throw new IllegalStateException("the task's end is told once, before the first run");
        }
        taskEndTold = true;
        WorldBeliefs.tellTeamTaskEnd(mas(), world().timeMs(), seconds);
    }

    /**
     * Runs {@code seconds} of simulated time (less when an agent fails at its job or {@link #stop});
     * the first run's end is the task's, told to every agent ({@link WorldBeliefs#tellTeamTaskEnd}).
     *
     * @throws IllegalStateException when the agent side fails
     * @throws IOException           with {@link #remoteController}, when a link cannot listen
     */
    public void runFor(double seconds) throws IOException, InterruptedException {
        if (!taskEndTold) {
            tellTaskEnd(seconds);
        }
        if (remote) {
            runRemote(seconds);
            return;
        }
        SimWorld world = world();
        List<RobotController> controllers = new ArrayList<>();
        for (TeamMember m : members) {
            ControllerConfig cc = ControllerConfig.defaults().withRobot(m.robot()).withLockstep(true).withLog(linkLog::add);
            if (stepLogs) {
                cc = cc.withEventLog(m.controllerLog()::add);
            }
            m.connect(InProcessLink.inMemory(world, cc, LinkConfig.defaults().withLog(linkLog::add)));
            controllers.add(m.controller());
        }
        TeamLockstep team = new TeamLockstep(world, controllers, this::agentsTurnOrFail).afterStep(now -> {
            if (failure == null) {
                watch.afterStep(now);
                afterStep(now);
            }
        });
        long end = world.timeMs() + Math.round(seconds * 1000);
        while (world.timeMs() < end && !stopRequested && failure == null && !team.interrupted()) {
            team.runner().stepOnce();
        }
        if (failure != null) {
            throw failure;
        }
    }

    /** The agents' turn of a team step: deliver every robot's step, reason once, answer every robot. */
    private void agentsTurnOrFail(long now) {
        if (failure != null) {
            return;
        }
        try {
            agentsTurn(now);
        } catch (RuntimeException e) {
            failure = e;
            members.forEach(m -> m.agentLeft("the agent side failed")); // no controller waits for an answer that will not come
        }
    }

    private void agentsTurn(long now) {
        advanceClockTo(now);
        LocalMAS mas = mas();
        for (TeamMember m : members) {
            StepData data = m.takeStep();
            if (data != null && !mas.isStopped()) {
                deliverStep(m.middlewareId(), data);
            }
        }
        if (!mas.isStopped()) {
            reason();
            departuresAfterReasoning(now);
            for (TeamMember m : members) {
                m.firstReasoningDone(mas);
            }
        }
        for (TeamMember m : members) {
            m.answer(stepLogs, onAnswer);
        }
    }

    /** After every robot's answer: a failed agent ends the run; progress. */
    private void afterStep(long now) {
        if (agentFailure().isPresent() || mas().isStopped()) {
            stopRequested = true;
        }
        onStep.accept(now);
    }
}
