package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpTarget;
import jacabot.cartago.SimulatedClock;
import jacabot.cartago.Workspace;
import jacabot.cartago.bridge.CartagoEnvironment;
import jacabot.cartago.bridge.JacaStepper;
import jacabot.experiments.link.StepData;
import jacabot.sim.SimWorld;
import java.io.PrintStream;
import java.util.List;

/**
 * The Jason and CArtAgO platform of a lockstep run, in simulated time: one clock, which the
 * artifacts' {@code await_time} and the agents' {@code .wait} both read; a stepped workspace; the
 * agents' MAS with that workspace as their environment; and the stepper that runs artifact steps
 * and reasoning cycles until the system is quiescent. A run on it ({@link LockstepRun}, one robot;
 * {@link TeamLockstepRun}, a team) makes the middleware artifacts and the agents, and each control
 * step advances the clock to the step's time, delivers the readings and lets the agents reason.
 */
public abstract class SteppedPlatform implements AutoCloseable {
    /** At most this many reasoning cycles per control step and agent (a busy agent cannot stall the world). */
    static final long CYCLES_PER_STEP = 20_000;

    private final SimWorld world;
    private final SimulatedClock clock = new SimulatedClock();
    private final Workspace workspace;
    private final LocalMAS mas;
    private final JacaStepper stepper;
    /** Who delivers the readings to the middleware artifacts (not an agent). */
    private final AgentId host;
    private long cycles;

    SteppedPlatform(SimWorld world, long seed, PrintStream console) {
        this.world = world;
        workspace = Workspace.builder("main").stepped().clock(clock).console(console)
                .logger(CartagoLogger.console(console)).build();
        mas = new LocalMAS(clock::nowMillis, console, seed);
        mas.setEnvironment(new CartagoEnvironment(workspace), List.of());
        stepper = new JacaStepper(mas, workspace);
        host = workspace.join("runner", new ArtifactObserverAdapter());
    }

    public SimWorld world() {
        return world;
    }

    public LocalMAS mas() {
        return mas;
    }

    /** {@return the run's workspace (read it, e.g. the inspector's artifacts panel; the run drives it)} */
    public Workspace workspace() {
        return workspace;
    }

    /** {@return the reasoning cycles run so far} */
    public long cycles() {
        return cycles;
    }

    SimulatedClock clock() {
        return clock;
    }

    JacaStepper stepper() {
        return stepper;
    }

    /** Moves the simulated clock on to a step's time {@code simTimeMs} (never back). */
    void advanceClockTo(long simTimeMs) {
        long lag = simTimeMs - clock.nowMillis();
        if (lag > 0) {
            clock.advance(lag);
        }
    }

    /**
     * Gives a control step's readings to a middleware artifact, on this thread when it is the next
     * artifact step anyway (two thread hand-offs fewer per control step).
     */
    void deliverStep(ArtifactId middleware, StepData data) {
        workspace.execOpInline(host, OpTarget.id(middleware), "deliverStep", new Object[] {data}, outcome -> {
        });
    }

    /** Runs artifact steps and reasoning cycles until quiescent or {@code cycleBudget} cycles, counted in {@link #cycles}. */
    void reason(long cycleBudget) {
        cycles += stepper.runUntilQuiescent(cycleBudget);
    }

    /**
     * Disposes the run's artifacts and ends its workspace's operation threads (they would idle
     * for 30 s otherwise, one per run of a sweep). The agents' state and the run's figures stay
     * readable; the run cannot go on.
     */
    @Override
    public void close() {
        workspace.close();
    }
}
