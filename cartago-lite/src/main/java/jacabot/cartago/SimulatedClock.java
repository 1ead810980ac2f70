package jacabot.cartago;

/**
 * Simulated time, advanced explicitly by the simulation (e.g. once per world step). Threads
 * sleeping in {@link #sleepUntil(long)} wake when {@link #advance(long)} reaches their deadline; a
 * stepped workspace wakes its {@code await_time}s in deadline order at its next
 * {@link Workspace#runPending()}.
 */
public final class SimulatedClock implements ArtifactClock {
    private long now;
    private int sleepers;

    /** Starts at time 0. */
    public SimulatedClock() {
        this(0);
    }

    /** Starts at {@code startMillis}. */
    public SimulatedClock(long startMillis) {
        this.now = startMillis;
    }

    @Override
    public synchronized long nowMillis() {
        return now;
    }

    /** Moves time forward by {@code millis} (not negative) and wakes the sleepers that are due. */
    public synchronized void advance(long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("simulated time cannot go back: advance(" + millis + ")");
        }
        now += millis;
        notifyAll();
    }

    @Override
    public synchronized void sleepUntil(long deadlineMillis) throws InterruptedException {
        sleepers++;
        try {
            while (now < deadlineMillis) {
                wait();
            }
        } finally {
            sleepers--;
        }
    }

    /**
     * {@return how many threads sleep in {@link #sleepUntil(long)}}; a threaded simulation can wait
     * for its artifacts to be asleep before advancing, so that no wake-up is missed.
     */
    public synchronized int sleepers() {
        return sleepers;
    }
}
