package jacabot.app.run;
import jacabot.robot.Experiment;
import jacabot.experiments.link.LinkTimings;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.Clock;
import jacabot.agent.runtime.LocalMAS;
import jacabot.cartago.CAgentArch;
import jacabot.cartago.CartagoEnvironment;
import jacabot.cartago.CartagoException;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.Workspace;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.robot.ControllerConfig;
import jacabot.robot.RobotController;
import jacabot.sim.SimRunner;
import jacabot.sim.SimWorld;
import java.io.PrintStream;
import java.util.List;

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

    public RealTimeRun(SimWorld world, Experiment experiment, String agentSource, String agentFile, long seed,
            double speed, PrintStream console) throws AslSyntaxException, CartagoException {
        this.world = world;
        workspace = Workspace.builder("main").console(console).logger(CartagoLogger.console(console)).build();
        Clock simTime = world::timeMs;
        mas = new LocalMAS(simTime, console, seed);
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        // the middleware listens on a free loopback port; the agent's !init finds it
        var id = workspace.createArtifact("middleware", Middlewares.of(experiment).getName(), 0);
        int port = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow().link().port();
        middleware = workspace.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
        var parser = new AslParser();
        // the world's landmarks reach the agent as initial beliefs (issue 13)
        var program = WorldBeliefs.inject(parser.parse(agentSource, agentFile), world.spec());
        var agent = mas.createAgent("robot", program, parser, CAgentArch::new);
        // reactive time: a reading that changed a percept, from its sampling to the plan it triggers
        agent.setPlanListener((event, plan) -> {
            if (event.isExternal() && event.trigger().literal() instanceof jacabot.agent.syntax.Literal l
                    && l.getAnnot("percept_type") != null) {
                var reading = middleware.takeTrigger();
                if (reading != null) {
                    middleware.link().timings().planTriggered(reading);
                }
            }
        });
        controller = new RobotController(world, ControllerConfig.defaults().withAddress("127.0.0.1", port)
                .withSpeedFactor(speed).withLog(line -> console.println("[controller] " + line)));
    }

    public SimRunner runner() {
        return controller.runner();
    }

    public SimWorld world() {
        return world;
    }

    /** {@return the link's timings (transport, delivery, reactive, response)} */
    public jacabot.experiments.link.LinkTimings timings() {
        return middleware.link().timings();
    }

    /** Starts the agents and the controller; the caller runs the simulation ({@link #runner()}). */
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
    }

    @Override
    public void close() {
        controller.close();
        mas.stop();
        workspace.close();
    }
}
