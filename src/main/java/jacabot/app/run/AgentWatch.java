package jacabot.app.run;

import jacabot.agent.runtime.LocalMAS;
import jacabot.agent.semantics.Agent;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/**
 * Whether the agents reason: the liveness probe behind the middleware's heartbeats
 * ({@link jacabot.experiments.link.MiddlewareLink#setLiveness}). An agent reasons when its reasoning
 * cycle count moved since the last look, or when it is idle (nothing to do until an event comes). One
 * that has work and has not finished a cycle for {@code stallMs} does not: a cycle that never ends,
 * or a thread that died with events waiting. Read from the heartbeat thread; {@link Agent#canSleep()}
 * is read without the agent's lock, so a look that fails counts as "not sure yet", never as alive.
 */
public final class AgentWatch implements BooleanSupplier {
    private final LocalMAS mas;
    private final long stallNanos;
    private final Map<String, long[]> seen = new HashMap<>(); // name -> {cycles, nanos of the last progress}

    public AgentWatch(LocalMAS mas, long stallMs) {
        this.mas = mas;
        this.stallNanos = TimeUnit.MILLISECONDS.toNanos(stallMs);
    }

    /** {@return whether every agent is idle now (nothing to do until an event comes)} */
    public boolean idle() {
        for (String name : mas.agentNames()) {
            try {
                if (!mas.agent(name).canSleep()) {
                    return false;
                }
            } catch (RuntimeException e) {
                return false;
            }
        }
        return true;
    }

    @Override
    public synchronized boolean getAsBoolean() {
        if (mas.isStopped()) {
            return false;
        }
        long now = System.nanoTime();
        for (String name : mas.agentNames()) {
            Agent a = mas.agent(name);
            long cycles = a.cycles();
            long[] s = seen.computeIfAbsent(name, n -> new long[] {cycles, now});
            if (cycles != s[0]) {
                s[0] = cycles;
                s[1] = now;
                continue;
            }
            boolean idle;
            try {
                idle = a.canSleep();
            } catch (RuntimeException e) {
                idle = false;
            }
            if (idle) {
                s[1] = now;
            } else if (now - s[1] > stallNanos) {
                return false;
            }
        }
        return true;
    }
}
