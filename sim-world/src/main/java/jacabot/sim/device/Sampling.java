package jacabot.sim.device;

import java.util.function.LongSupplier;

/**
 * The Webots sensor triad: {@code enable(period)}, {@code disable()}, {@code getSamplingPeriod()}.
 * The first reading is available one period after {@code enable}, then every period; readings
 * are taken on the world's physics steps, so a period that is not a multiple of the basic time
 * step is rounded up to the next step.
 */
public final class Sampling {
    private final LongSupplier clock;
    private int period;
    private long next;
    private boolean ready;

    /** @param clock the world's simulated time in milliseconds */
    public Sampling(LongSupplier clock) {
        this.clock = clock;
    }

    /** Starts sampling every {@code periodMs} milliseconds; clears the reading. */
    public void enable(int periodMs) {
        if (periodMs <= 0) {
            throw new IllegalArgumentException("sampling period must be > 0 ms, got " + periodMs);
        }
        period = periodMs;
        next = clock.getAsLong() + periodMs;
        ready = false;
    }

    /** Stops sampling; clears the reading. */
    public void disable() {
        period = 0;
        ready = false;
    }

    /** {@return the sampling period in ms, 0 when disabled} */
    public int period() {
        return period;
    }

    /** {@return whether a reading has been taken since the last enable} */
    public boolean ready() {
        return ready;
    }

    /** {@return whether a reading is due at this time; if so, schedules the next one} */
    public boolean due(long nowMs) {
        if (period == 0 || nowMs < next) {
            return false;
        }
        while (next <= nowMs) {
            next += period;
        }
        ready = true;
        return true;
    }
}
