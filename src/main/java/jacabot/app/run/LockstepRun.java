package jacabot.app.run;
import jacabot.robot.Experiment;
import jacabot.experiments.link.LatencyStats;
import jacabot.experiments.link.LatencyRecorder;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.runtime.SimulatedClock;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CAgentArch;
import jacabot.cartago.CartagoEnvironment;
import jacabot.cartago.CartagoException;
import jacabot.cartago.OpTarget;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.JacaStepper;
import jacabot.experiments.MiddlewareArtifact;
import jacabot.experiments.link.StepData;
import jacabot.robot.link.Command;
import jacabot.sim.SimWorld;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * An experiment with the agent in the loop, in lockstep: each control step the world's readings
 * reach the middleware artifact, the agent reasons until it is idle, its commands go back, and
 * only then does the world advance. Agents, artifacts and the world all run in simulated time,
 * so a run is as fast as the machine allows and replays exactly under a seed.
 */
public final class LockstepRun {
    /** At most this many reasoning cycles per control step (a busy agent cannot stall the world). */
    static final long CYCLES_PER_STEP = 20_000;

    private final SimWorld world;
    private final String robotName;
    private final SimulatedClock agentClock = new SimulatedClock();
    private final jacabot.cartago.SimulatedClock artifactClock = new jacabot.cartago.SimulatedClock();
    private final Workspace workspace;
    private final LocalMAS mas;
    private final JacaStepper stepper;
    private final AgentId host;
    private final ArtifactId middlewareId;
    private final MiddlewareArtifact middleware;
    private long cycles;
    /** Reactive time: from a step's readings reaching the middleware to the first plan they trigger. */
    private final jacabot.experiments.link.LatencyRecorder reactive = new jacabot.experiments.link.LatencyRecorder(1_000_000);
    private long deliveredNanos;
    private long inlineNanos;
    private boolean reactedThisStep = true;
    private boolean stepLogs = true;
    private Consumer<StepData> onStep = d -> {
    };

    /**
     * @param agentSource the agent's program text; {@code agentFile} names it in messages
     */
    public LockstepRun(SimWorld world, String robotName, Experiment experiment, String agentSource, String agentFile,
            long seed, PrintStream console) throws AslSyntaxException, CartagoException {
        this.world = world;
        this.robotName = robotName;
        workspace = Workspace.builder("main").stepped().clock(artifactClock).console(console)
                .logger(jacabot.cartago.CartagoLogger.console(console)).build();
        mas = new LocalMAS(agentClock, console, seed);
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        stepper = new JacaStepper(mas, workspace);
        host = workspace.join("runner", new ArtifactObserverAdapter());
        // made before the agent starts, so its !init finds it (thesis Chapter 4 §5)
        middlewareId = workspace.createArtifact("middleware", Middlewares.of(experiment).getName(), 0, "lockstep");
        middleware = workspace.artifactObject(middlewareId, MiddlewareArtifact.class).orElseThrow();
        var parser = new AslParser();
        // the world's landmarks reach the agent as initial beliefs (issue 13)
        AgentProgram program = WorldBeliefs.inject(parser.parse(agentSource, agentFile), world.spec());
        var agent = mas.createAgent("robot", program, parser, CAgentArch::new);
        agent.setPlanListener((event, plan) -> {
            if (!reactedThisStep && event.isExternal() && isPercept(event)) {
                reactedThisStep = true;
                reactive.record((System.nanoTime() - deliveredNanos) / 1000);
            }
        });
    }

    private static boolean isPercept(jacabot.agent.semantics.Event e) {
        return e.trigger().literal() instanceof Literal l && l.getAnnot("percept_type") != null;
    }

    /** {@return the artifact steps run so far (each runs on an operation thread: two thread hand-offs)} */
    public long artifactSteps() {
        return stepper.artifactSteps();
    }

    /** {@return wall-clock ns spent so far: artifact steps, reasoning cycles} */
    public long[] agentSideCost() {
        return new long[] {stepper.artifactNanos() + inlineNanos, stepper.reasoningNanos()};
    }

    /** {@return the reactive times measured so far (wall clock, microseconds)} */
    public jacabot.experiments.link.LatencyStats reactiveTimes() {
        return reactive.stats();
    }

    /** Called after each control step's exchange (progress lines, recorders). */
    public void onStep(Consumer<StepData> listener) {
        this.onStep = listener;
    }

    public SimWorld world() {
        return world;
    }

    public LocalMAS mas() {
        return mas;
    }

    public long cycles() {
        return cycles;
    }

    /** Whether the result keeps a line per step on both sides (on by default; see {@link LockstepCoordinator#stepLogs}). */
    public LockstepRun stepLogs(boolean keep) {
        this.stepLogs = keep;
        return this;
    }

    /** Runs {@code seconds} of simulated time. */
    public LockstepCoordinator.Result runFor(double seconds) throws IOException, InterruptedException {
        var coordinator = new LockstepCoordinator(world, robotName, this::step).stepLogs(stepLogs);
        return coordinator.runFor(seconds);
    }

    private List<Command> step(StepData data) {
        agentClock.set(data.simTimeMs());
        long lag = data.simTimeMs() - artifactClock.nowMillis();
        if (lag > 0) {
            artifactClock.advance(lag);
        }
        if (!mas.isStopped()) {
            deliveredNanos = System.nanoTime();
            reactedThisStep = false;
            // on this thread when it is the next step anyway: two thread hand-offs fewer per control step
            long t0 = System.nanoTime();
            workspace.execOpInline(host, OpTarget.id(middlewareId), "deliverStep", new Object[] {data}, outcome -> {
            });
            inlineNanos += System.nanoTime() - t0;
            cycles += stepper.runUntilQuiescent(CYCLES_PER_STEP);
        }
        onStep.accept(data);
        return new ArrayList<>(middleware.takeCommands());
    }

    /** Sets a belief of the agent's program before it starts, e.g. {@code middlewarePort(0)}. */
    static String withBelief(String source, String functor, double value) {
        return source.replaceAll(functor + "\\([^)]*\\)\\.", Literal.of(functor, new NumberTerm(value)) + ".");
    }
}
