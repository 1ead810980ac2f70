package jacabot.experiments.link;

import java.util.function.LongConsumer;

/**
 * Lockstep with the agent in its own thread: a step's {@code STEP_ACK} goes out only once the agent
 * reasons and is idle ({@link AgentProbes}), so a stuck agent holds the world still instead of
 * letting it run without a mind. A step that cannot be acknowledged yet waits here; the
 * {@link Heartbeat} thread retries it every millisecond.
 */
final class StepAcknowledgement {
    private final AgentProbes agent;
    private final LongConsumer acknowledge;
    /** The step waiting for its acknowledgement, −1: none. */
    private volatile long pending = -1;

    StepAcknowledgement(AgentProbes agent, LongConsumer acknowledge) {
        this.agent = agent;
        this.acknowledge = acknowledge;
    }

    /** Acknowledges {@code step} now if the agent reasons and is idle, else keeps it for {@link #retry}. */
    void whenAlive(long step) {
        if (agent.alive() && agent.idle()) {
            pending = -1;
            acknowledge.accept(step);
        } else {
            pending = step;
        }
    }

    boolean waiting() {
        return pending >= 0;
    }

    /** Acknowledges the waiting step, if any, once the agent reasons and is idle. */
    void retry() {
        long step = pending;
        if (step >= 0 && agent.alive() && agent.idle()) {
            pending = -1;
            acknowledge.accept(step);
        }
    }
}
