package jacabot.agent.runtime;

import jacabot.agent.semantics.Clock;

/**
 * Simulated time for {@link LocalMAS#runSimulated}: it stands still while agents reason and is
 * moved on only by the run, to the next timer due, once every agent is idle. A {@code .wait(300)}
 * then costs no real time, and the agents have done all they could before it ends, however
 * loaded the machine is. Starts at 0 (midnight for {@code .time}).
 */
public final class SimulatedTime implements Clock {
    private volatile long now;

    @Override
    public long millis() {
        return now;
    }

    /** Moves time on to {@code millis} (never back). */
    void advanceTo(long millis) {
        if (millis > now) {
            now = millis;
        }
    }
}
