package jacabot.app.run;

import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * How long the other side of a link has been silent, counted in the watcher's own waking time.
 * The watcher looks once a second; a look that comes much later than that means this process was
 * stopped (Ctrl-Z, SIGSTOP, a host that paused it), and the stop is not the other side's silence:
 * a sweep suspended for minutes and resumed would otherwise fail every run it had in flight.
 */
final class SilenceWatch {
    /** The most one look adds to the silence: a little over the watcher's one-second period. */
    static final long LOOK_NANOS = TimeUnit.SECONDS.toNanos(2);

    private final long limitNanos;
    private final LongSupplier clock;
    private volatile long heardAt;
    private long lastLook;
    private long heardAtLastLook;
    private long silentNanos;

    SilenceWatch(long limitSeconds, LongSupplier clock) {
        this.limitNanos = TimeUnit.SECONDS.toNanos(limitSeconds);
        this.clock = clock;
        this.heardAt = clock.getAsLong();
        this.lastLook = heardAt;
        this.heardAtLastLook = heardAt;
    }

    SilenceWatch(long limitSeconds) {
        this(limitSeconds, System::nanoTime);
    }

    /** The other side sent something (any thread). */
    void heard() {
        heardAt = clock.getAsLong();
    }

    /** One look (the watching thread only): whether the silence is now over the limit. */
    boolean tooLong() {
        long now = clock.getAsLong();
        long heard = heardAt;
        if (heard != heardAtLastLook) {
            heardAtLastLook = heard;
            silentNanos = Math.min(now - heard, LOOK_NANOS);
        } else {
            silentNanos += Math.min(now - lastLook, LOOK_NANOS);
        }
        lastLook = now;
        return silentNanos > limitNanos;
    }
}
