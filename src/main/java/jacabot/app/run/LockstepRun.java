package jacabot.app.run;
import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Event;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.CartagoException;
import jacabot.cartago.bridge.CAgentArch;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.link.LatencyRecorder;
import jacabot.experiments.link.LatencyStats;
import jacabot.experiments.link.StepData;
import jacabot.robot.Experiment;
import jacabot.robot.link.Command;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.BiConsumer;
import java.util.function.Consumer;

/**
 * An experiment with the agent in the loop, in lockstep: each control step the world's readings
 * reach the middleware artifact, the agent reasons until it is idle, its commands go back, and
 * only then does the world advance. Agents, artifacts and the world all run in simulated time,
 * so a run is as fast as the machine allows and replays exactly under a seed. A robot may be
 * programmed by several agents sharing its middleware artifact ({@link RobotAgent}): all of them
 * reason every step until the system is idle. Its clock, workspace and agents are the
 * {@link SteppedPlatform}'s.
 */
public final class LockstepRun extends SteppedPlatform {
    private final String robotName;
    private final Experiment experiment;
    private final ArtifactId middlewareId;
    private final MiddlewareArtifact middleware;
    /** Reactive time: from a step's readings reaching the middleware to the first plan they trigger. */
    private final LatencyRecorder reactive = new LatencyRecorder(1_000_000);
    private long deliveredNanos;
    private long inlineNanos;
    private boolean reactedThisStep = true;
    private boolean stepLogs = true;
    private Consumer<String> controllerLogSink;
    private int port;
    private boolean remoteController;
    private boolean inMemory;
    private boolean turns;
    private boolean pipeline;
    private volatile LockstepCoordinator coordinator;
    /** The robot's agents, in the order they were made (each reasons every step, in this order). */
    private final List<Member> members = new ArrayList<>();
    private boolean reasoned;
    private Consumer<StepData> onStep = d -> {
    };
    private BiConsumer<StepData, List<Command>> onCommands = (d, c) -> {
    };
    private volatile Consumer<Agent> beforeCycle;
    private Runnable afterAnswer = () -> {
    };

    /** One agent of the robot and what watches it for failures. */
    private record Member(String name, FailureWatch failures, List<Literal> initialGoals) {
    }

    /**
     * @param agent the agent's program (its includes are read from where it came from), named
     *              {@value RobotAgent#ALONE}
     */
    public LockstepRun(SimWorld world, String robotName, Experiment experiment, AgentSource agent,
            long seed, PrintStream console) throws AslSyntaxException, CartagoException {
        this(world, robotName, experiment, List.of(new RobotAgent(RobotAgent.ALONE, agent)), seed, console);
    }

    /**
     * The robot programmed by several agents sharing its middleware artifact (the thesis' Chapter 6
     * wish): each step, all of them reason until the system is idle; the middleware lends the wheels
     * to one at a time ({@link MiddlewareArtifact#wheelLease}).
     *
     * @param agents the robot's agents, at least one, names unique
     */
    public LockstepRun(SimWorld world, String robotName, Experiment experiment, List<RobotAgent> agents,
            long seed, PrintStream console) throws AslSyntaxException, CartagoException {
        super(world, seed, console);
        if (agents.isEmpty() || agents.stream().map(RobotAgent::name).distinct().count() != agents.size()) {
            close();
            throw new IllegalArgumentException("a robot needs one or more agents with distinct names, got " + agents);
        }
        this.robotName = robotName;
        this.experiment = experiment;
        // made before the agent starts, so its !init finds it (thesis Chapter 4 §5)
        middlewareId = workspace().createArtifact("middleware", Middlewares.of(experiment).getName(), 0, "lockstep");
        middleware = workspace().artifactObject(middlewareId, MiddlewareArtifact.class).orElseThrow();
        for (RobotAgent agent : agents) {
            members.add(createAgent(agent, experiment));
        }
    }

    private Member createAgent(RobotAgent agent, Experiment experiment) throws AslSyntaxException {
        AslParser parser = agent.source().parser();
        // the world's landmarks reach the agent as initial beliefs (not in the thesis: so that other worlds work)
        AgentProgram program = WorldBeliefs.inject(agent.source().parse(parser), world().spec(), experiment);
        var member = new Member(agent.name(), new FailureWatch(program.goals()), program.goals());
        watch(agent.name(), member.failures());
        Agent robot = mas().createAgent(agent.name(), program, parser, local -> new CAgentArch(local) {
            @Override
            public void sense(Agent a) { // the start of each reasoning cycle, on the run's thread
                Consumer<Agent> hook = beforeCycle;
                if (hook != null) {
                    hook.accept(a);
                }
                super.sense(a);
            }
        });
        robot.setUnhandledFailureListener((failure, root) -> member.failures().failureUnhandled(failure, root, clock().nowMillis()));
        robot.setPlanListener((event, plan) -> {
            member.failures().planSelected(event, clock().nowMillis());
            if (!reactedThisStep && event.isExternal() && isPercept(event)) {
                reactedThisStep = true;
                reactive.record((System.nanoTime() - deliveredNanos) / 1000);
            }
        });
        return member;
    }

    private static boolean isPercept(Event e) {
        return e.trigger().literal() instanceof Literal l && l.getAnnot("percept_type") != null;
    }

    /** {@return the last run's threads' CPU and system time ({@link LockstepCoordinator#threadCpuNanos}), −1 each before a run} */
    public long[] threadCpuNanos() {
        LockstepCoordinator c = coordinator;
        return c != null ? c.threadCpuNanos() : new long[] {-1, -1, -1, -1};
    }

    /** {@return the artifact steps run so far (on an operation thread, or on this one when the operation never waits)} */
    public long artifactSteps() {
        return stepper().artifactSteps();
    }

    /** {@return wall-clock ns spent so far: artifact steps, reasoning cycles} */
    public long[] agentSideCost() {
        return new long[] {stepper().artifactNanos() + inlineNanos, stepper().reasoningNanos()};
    }

    /** {@return the reactive times measured so far (wall clock, microseconds)} */
    public LatencyStats reactiveTimes() {
        return reactive.stats();
    }

    /** {@return the reactive times kept, in microseconds (for a histogram)} */
    public long[] reactiveSamples() {
        return reactive.samples();
    }

    /** Called after each control step's exchange (progress lines, recorders). */
    public void onStep(Consumer<StepData> listener) {
        this.onStep = listener;
    }

    /** Called after each control step with its readings and the commands going to the robot (inspector, step log). */
    public void onCommands(BiConsumer<StepData, List<Command>> listener) {
        this.onCommands = listener;
    }

    /**
     * Called on the agent side's thread after each step's answer has gone to the controller, before
     * the next step: the agents are idle, the world may be advancing (so read the agents, not the
     * world). What is done here is off the step's critical path in lockstep: the world simulates meanwhile.
     */
    public void afterAnswer(Runnable listener) {
        this.afterAnswer = listener;
    }

    /**
     * Called at the start of each reasoning cycle of an agent, on the run's thread, between two
     * cycles (the debugger's one-cycle step). It must not change the agent.
     */
    public void beforeCycle(Consumer<Agent> hook) {
        this.beforeCycle = hook;
    }

    /** Whether the result keeps a line per step on both sides (on by default; see {@link LockstepCoordinator#stepLogs}). */
    public LockstepRun stepLogs(boolean keep) {
        this.stepLogs = keep;
        return this;
    }

    /** Streams the controller's event log to {@code sink} instead of keeping it ({@link LockstepCoordinator#controllerLogTo}). */
    public LockstepRun controllerLogTo(Consumer<String> sink) {
        this.controllerLogSink = sink;
        return this;
    }

    /** The link listens on {@code listenPort} (0: a free one). */
    public LockstepRun port(int listenPort) {
        this.port = listenPort;
        return this;
    }

    /**
     * The controller is another process ({@code jacabot controller --lockstep --port P}); see
     * {@link LockstepCoordinator#remoteController}: the same run as in one process, step for step.
     */
    public LockstepRun remoteController(boolean on) {
        this.remoteController = on;
        return this;
    }

    /** Over the socket, the simulation thread takes the middleware's turns ({@link LockstepCoordinator#takeTurns}); off by default. */
    public LockstepRun takeTurns(boolean on) {
        this.turns = on;
        return this;
    }

    /**
     * A pipelined lockstep ({@link LockstepCoordinator#pipeline}): the world simulates the next step
     * while the agent reasons, its answer applied one control step later. Off by default.
     */
    public LockstepRun pipeline(boolean on) {
        this.pipeline = on;
        return this;
    }

    /** The link's frames go through memory, not a loopback socket ({@link LockstepCoordinator#inMemory}): sweeps. */
    public LockstepRun inMemory(boolean on) {
        this.inMemory = on;
        return this;
    }

    /** {@return with {@link #remoteController}, the port the agent side listens on once it does (0 before)} */
    public int listeningPort() {
        LockstepCoordinator c = coordinator;
        return c != null ? c.listeningPort() : 0;
    }

    /**
     * {@return why the agent failed at its job, if it has} (no plan for its initial goal, a
     * {@code .stopMAS} before the end, a failure storm: {@link FailureWatch}); the run ended at that step
     */
    public Optional<String> agentFailure() {
        for (Member m : members) {
            Optional<String> verdict = m.failures().verdict();
            if (verdict.isPresent()) {
                return members.size() == 1 ? verdict : Optional.of(m.name() + ": " + verdict.get());
            }
        }
        return Optional.empty();
    }

    /** {@return the names of the robot's agents, in the order they were made} */
    public List<String> agentNames() {
        return members.stream().map(Member::name).toList();
    }

    /** {@return the robot's middleware artifact (the wheels' holder and drivers: {@link MiddlewareArtifact#wheelLease})} */
    public MiddlewareArtifact middleware() {
        return middleware;
    }

    /** Ends a run in progress at the current step; {@link #runFor} returns what it has. */
    public void stop() {
        LockstepCoordinator c = coordinator;
        if (c != null) {
            c.stop();
        }
    }

    /** Runs {@code seconds} of simulated time (the first run's end is the task's: {@link WorldBeliefs#tellTaskEnd}). */
    public LockstepCoordinator.Result runFor(double seconds) throws IOException, InterruptedException {
        if (!reasoned) {
            WorldBeliefs.tellTaskEnd(mas(), experiment, world().timeMs(), seconds);
        }
        var c = new LockstepCoordinator(world(), robotName, this::step).stepLogs(stepLogs).port(port)
                .remoteController(remoteController).inMemory(inMemory).takeTurns(turns).pipeline(pipeline).afterAnswer(afterAnswer);
        if (controllerLogSink != null) {
            c.controllerLogTo(controllerLogSink);
        }
        coordinator = c;
        return c.runFor(seconds);
    }

    private List<Command> step(StepData data) {
        advanceClockTo(data.simTimeMs());
        LocalMAS mas = mas();
        if (!mas.isStopped()) {
            deliveredNanos = System.nanoTime();
            reactedThisStep = false;
            long t0 = System.nanoTime();
            deliverStep(middlewareId, data);
            inlineNanos += System.nanoTime() - t0;
            reason();
            if (!reasoned) {
                reasoned = true;
                members.forEach(m -> m.failures().firstReasoningDone(mas.agent(m.name()).planLibrary(), m.initialGoals()));
            }
            if (mas.isStopped()) {
                members.forEach(m -> m.failures().systemStopped(clock().nowMillis()));
            }
            LockstepCoordinator c = coordinator;
            if (agentFailure().isPresent() && c != null) {
                c.endAfterThisStep(); // a failed agent does not run out its duration
            }
        }
        onStep.accept(data);
        List<Command> commands = new ArrayList<>(middleware.takeCommands());
        onCommands.accept(data, commands);
        return commands;
    }

    /** Sets a belief of the agent's program before it starts, e.g. {@code middlewarePort(0)}. */
    static String withBelief(String source, String functor, double value) {
        return source.replaceAll(functor + "\\([^)]*\\)\\.", Literal.of(functor, new NumberTerm(value)) + ".");
    }
}
