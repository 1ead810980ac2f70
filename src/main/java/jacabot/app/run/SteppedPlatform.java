package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.Intention;
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
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * The Jason and CArtAgO platform of a lockstep run, in simulated time: one clock, which the
 * artifacts' {@code await_time} and the agents' {@code .wait} both read; a stepped workspace; the
 * agents' MAS with that workspace as their environment; and the stepper that runs artifact steps
 * and reasoning cycles until the system is quiescent. A run on it ({@link LockstepRun}, one robot;
 * {@link TeamLockstepRun}, a team) makes the middleware artifacts and the agents, and each control
 * step advances the clock to the step's time, delivers the readings and lets the agents reason.
 */
public abstract class SteppedPlatform implements AutoCloseable {
    /**
     * At most this many reasoning cycles per control step and agent: an agent that has not gone
     * idle by then loops without waiting (a plan that re-posts its goal at once, an action failing
     * again and again), and the run ends there as that agent's failure. Counted in cycles, not wall
     * time, so that it comes at the same step on any load. Normal runs stay far below (the most
     * measured in one step, docs/running.md: 487, four robots' agents together).
     */
    static final long CYCLES_PER_STEP = 20_000;

    private final SimWorld world;
    private final SimulatedClock clock = new SimulatedClock();
    private final Workspace workspace;
    private final LocalMAS mas;
    private final JacaStepper stepper;
    /** Who delivers the readings to the middleware artifacts (not an agent). */
    private final AgentId host;
    private long cycles;
    /** Each agent's failure watch, by name: told when the agent's reasoning runs away within a step. */
    private final Map<String, FailureWatch> watches = new LinkedHashMap<>();
    /** The watches' names, in their order. */
    private String[] watchedNames = new String[0];

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

    /** Agent {@code name}'s failures are {@code watch}'s: it is told when the agent's reasoning runs away ({@link #reason}). */
    void watch(String name, FailureWatch watch) {
        watches.put(name, watch);
        watchedNames = watches.keySet().toArray(new String[0]);
    }

    /**
     * A control step's reasoning: artifact steps and reasoning cycles until the system is quiescent,
     * counted in {@link #cycles}, at most {@link #CYCLES_PER_STEP} per agent. An agent still busy
     * then (the one that ran the most cycles in this step) has run away: its watch is told, and the
     * run ends after this step with that agent's failure.
     */
    void reason() {
        // the agents' cycles so far, in the watches' order (an array: this runs every control step)
        String[] names = watchedNames;
        long[] before = new long[names.length];
        for (int i = 0; i < names.length; i++) {
            before[i] = agentCycles(names[i]);
        }
        long budget = CYCLES_PER_STEP * Math.max(1, names.length);
        long run = stepper.runUntilQuiescent(budget);
        cycles += run;
        if (run < budget || allIdle(names)) {
            return;
        }
        String busiest = null;
        long most = -1;
        for (int i = 0; i < names.length; i++) {
            long n = agentCycles(names[i]) - before[i];
            if (n > most) {
                busiest = names[i];
                most = n;
            }
        }
        if (busiest != null) {
            long now = clock.nowMillis();
            watches.get(busiest).reasoningRanAway(most, now / Math.max(1, world.controlStep()), now, runningPlans(busiest));
        }
    }

    private boolean allIdle(String[] names) {
        for (String name : names) {
            Agent a = mas.agent(name);
            if (!(a == null || a.isStopped() || a.canSleep())) {
                return false;
            }
        }
        return true;
    }

    /**
     * {@return the labels of the plans atop agent {@code name}'s intentions that are ready to run or
     * wait for an event of theirs (a goal posted), each once}
     */
    private List<String> runningPlans(String name) {
        Agent a = mas.agent(name);
        Set<String> out = new LinkedHashSet<>();
        if (a != null) {
            Circumstance c = a.circumstance();
            Set<Intention> busy = new LinkedHashSet<>();
            for (Intention i : c.allIntentions()) {
                if (c.hasRunningIntention(i)) {
                    busy.add(i);
                }
            }
            c.eventList().stream().map(Event::intention).filter(Objects::nonNull).forEach(busy::add);
            for (Intention i : busy) {
                if (i.peek() != null && i.peek().plan().label() != null) {
                    out.add("@" + i.peek().plan().label().functor());
                }
            }
        }
        return List.copyOf(out);
    }

    private long agentCycles(String name) {
        Agent a = mas.agent(name);
        return a == null ? 0 : a.cycles();
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
