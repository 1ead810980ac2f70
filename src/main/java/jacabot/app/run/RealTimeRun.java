package jacabot.app.run;
import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Clock;
import jacabot.agent.semantics.Event;
import jacabot.agent.syntax.Literal;
import jacabot.cartago.CartagoException;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.CAgentArch;
import jacabot.cartago.bridge.CartagoEnvironment;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.link.LinkTimings;
import jacabot.robot.ControllerConfig;
import jacabot.robot.Experiment;
import jacabot.robot.RobotController;
import jacabot.robot.link.LinkSecret;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import java.io.PrintStream;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * An experiment in real time (× a speed factor), as the thesis ran it: the simulator paces the
 * world, the controller talks to the middleware over a loopback socket, and the agent runs free on
 * its own thread, reading simulated time from the world. Used with the viewer.
 */
public final class RealTimeRun implements AutoCloseable {
    private final SimWorld world;
    private final Workspace workspace;
    private final LocalMAS mas;
    private final RobotController controller;
    private final MiddlewareArtifact middleware;
    private Thread agents;
    private final LagMeter lag;
    private final FailureWatch failures;
    private final Experiment experiment;

    /** An agent stuck in one reasoning cycle this long stops the heartbeats (and so the robot). */
    public static final long STALL_MS = 100;

    public RealTimeRun(SimWorld world, Experiment experiment, AgentSource agent, long seed,
            double speed, PrintStream console) throws AslSyntaxException, CartagoException {
        this(world, experiment, agent, seed, speed, console, 0);
    }

    /** @param port where the middleware listens (0: a free loopback port) */
    public RealTimeRun(SimWorld world, Experiment experiment, AgentSource agent, long seed,
            double speed, PrintStream console, int port) throws AslSyntaxException, CartagoException {
        this(world, experiment, agent, seed, speed, console, port, null);
    }

    /**
     * @param controllerEvents the controller's event log (a line per reading batch, applied command
     *                         and pose, on the simulation thread; e.g. for the step log), or null
     */
    public RealTimeRun(SimWorld world, Experiment experiment, AgentSource agent, long seed,
            double speed, PrintStream console, int port, Consumer<String> controllerEvents)
            throws AslSyntaxException, CartagoException {
        this.world = world;
        this.experiment = experiment;
        // both ends are in this process: a fresh secret of this run's, no file needed
        LinkSecret.useInThisProcess(LinkSecret.random());
        workspace = Workspace.builder("main").console(console).logger(CartagoLogger.console(console)).build();
        Clock simTime = world::timeMs;
        mas = new LocalMAS(simTime, console, seed);
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        // the middleware listens on a free loopback port; the agent's !init finds it
        var id = workspace.createArtifact("middleware", Middlewares.of(experiment).getName(), port);
        int boundPort = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow().link().port();
        middleware = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
        AslParser parser = agent.parser();
        // the world's landmarks reach the agent as initial beliefs (not in the thesis: so that other worlds work)
        var program = WorldBeliefs.inject(agent.parse(parser), world.spec(), experiment);
        // reactive time: a reading that changed a percept, from its sampling to the plan it triggers
        failures = new FailureWatch(program.goals());
        Agent robot = mas.createAgent("robot", program, parser, CAgentArch::new);
        robot.setUnhandledFailureListener((failure, root) -> failures.failureUnhandled(failure, root, world.timeMs()));
        robot.setPlanListener((event, plan) -> {
            failures.planSelected(event, world.timeMs());
            timeReaction(event);
            if (event.isExternal() && event.trigger().literal() instanceof Literal l
                    && l.getAnnot("percept_type") != null) {
                var reading = middleware.takeTrigger();
                if (reading != null) {
                    middleware.link().timings().planTriggered(reading);
                }
            }
        });
        // heartbeats only while the agent reasons: a stuck or dead agent lets the fail-safe stop the robot
        middleware.link().setLiveness(new AgentWatch(mas, STALL_MS));
        controller = new RobotController(world, ControllerConfig.defaults().withAddress("127.0.0.1", boundPort)
                .withSpeedFactor(speed).withLog(line -> console.println("[controller] " + line))
                .withEventLog(controllerEvents));
        lag = new LagMeter(controller.runner());
        for (String name : mas.agentNames()) {
            lag.watch(mas.agent(name));
        }
    }

    /** On the agent's thread: a plan was chosen for {@code event} (the meter is made before the agent runs). */
    private void timeReaction(Event event) {
        lag.planSelected(event);
    }

    /**
     * {@return why the agent failed at its job, if it has}: a {@code .stopMAS} or a failure storm
     * ({@link FailureWatch}); the caller ends the run. Looked at by the caller every few hundred ms.
     */
    public Optional<String> agentFailure() {
        if (mas.isStopped()) {
            failures.systemStopped(world.timeMs());
        }
        return failures.verdict();
    }

    /** {@return how far the run falls behind real time (sampling from {@link #start()} on)} */
    public LagMeter lag() {
        return lag;
    }

    public SimRunner runner() {
        return controller.runner();
    }

    /** {@return the agents (e.g. for the inspector: attach before {@link #start()})} */
    public LocalMAS mas() {
        return mas;
    }

    public SimWorld world() {
        return world;
    }

    /** {@return the link's timings (transport, delivery, reactive, response)} */
    public LinkTimings timings() {
        return middleware.link().timings();
    }

    /**
     * Starts the agents and the controller, telling the agents that their task ends in {@code seconds}
     * ({@link WorldBeliefs#tellTaskEnd}); the caller runs the simulation that long ({@link #runner()}).
     */
    public void start(double seconds) {
        WorldBeliefs.tellTaskEnd(mas, experiment, world.timeMs(), seconds);
        start();
    }

    /** Starts the agents and the controller, a run with no set end; the caller runs the simulation ({@link #runner()}). */
    public void start() {
        agents = new Thread(() -> {
            try {
                mas.runThreads();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "agents");
        agents.setDaemon(true);
        agents.start();
        controller.start();
        lag.start();
    }

    @Override
    public void close() {
        lag.close();
        controller.close();
        mas.stop();
        workspace.close();
    }
}
