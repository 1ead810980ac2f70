package jacabot.agent.runtime;

import jacabot.agent.semantics.Clock;

/** A clock that only moves when told to (by a simulator or a test). Thread-safe. */
public final class SimulatedClock implements Clock {
    private volatile long now;

    @Override
    public long millis() {
        return now;
    }

    /** Sets the time; earlier times are ignored so that the clock never goes back. */
    public synchronized void set(long millis) {
        if (millis > now) {
            now = millis;
        }
    }

    public synchronized void advance(long millis) {
        now += Math.max(0, millis);
    }
}
