package jacabot.app.inspector;

import jacabot.agent.semantics.Agent;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Watches one agent for the inspector and the step log: its {@link MindProbe}, its history and,
 * for a robot, where its body is. {@link #capture()} must run on the agent's thread between two
 * reasoning cycles: lockstep runs call it after each control step (the agents are idle then);
 * agents on their own threads are sampled with {@link #sampleEvery}, which has the capture run at
 * the start of one of the agent's cycles.
 */
public final class MindWatch {
    private final Agent agent;
    private final MindProbe probe;
    private final MindHistory history;
    private final Supplier<RobotView> robot;
    private Consumer<MindState> also = m -> {
    };

    private MindWatch(Agent agent, MindHistory history, Supplier<RobotView> robot) {
        this.agent = agent;
        this.probe = MindProbe.attach(agent);
        this.history = history;
        this.robot = robot;
    }

    /**
     * Watches {@code agent}; call before it runs.
     *
     * @param inspector where its frames go, or null (e.g. only a step log)
     * @param robot its body now, or null for an agent without one
     */
    public static MindWatch attach(Inspector inspector, Agent agent, Supplier<RobotView> robot) {
        return new MindWatch(agent, inspector == null ? null : inspector.add(agent.name()), robot);
    }

    /** Also hands every captured state to {@code sink} (e.g. the step log), on the agent's thread. */
    public MindWatch alsoTo(Consumer<MindState> sink) {
        this.also = sink;
        return this;
    }

    /** Captures the mind now; on the agent's thread, between cycles. {@return the state} */
    public MindState capture() {
        MindState m = probe.capture();
        if (history != null) {
            history.record(m, robot == null ? null : robot.get(), probe.plans());
        }
        also.accept(m);
        return m;
    }

    /** {@return the mind at the start of a reasoning cycle (on the agent's thread), the step log's selections left alone} */
    public MindState peekBeforeCycle() {
        return probe.peek(agent.cycles() - 1);
    }

    /** {@return whether this watches {@code a}} */
    public boolean watches(Agent a) {
        return agent == a;
    }

    /**
     * Samples agents running on their own threads: every {@code periodMs} each agent captures its
     * mind at the start of its next cycle. {@return a handle that stops the sampling}
     */
    public static AutoCloseable sampleEvery(List<MindWatch> watches, long periodMs) {
        ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "inspector-sampler");
            t.setDaemon(true);
            return t;
        });
        timer.scheduleAtFixedRate(() -> watches.forEach(w -> w.agent.runAtBeginOfNextCycle(w::capture)), 0, periodMs,
                TimeUnit.MILLISECONDS);
        return timer::shutdownNow;
    }
}
