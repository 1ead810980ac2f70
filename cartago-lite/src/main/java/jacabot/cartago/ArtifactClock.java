package jacabot.cartago;

/**
 * The time source of {@link Artifact#await_time(long)}: the wall clock by default, a
 * {@link SimulatedClock} when the workspace runs in simulated time.
 */
public interface ArtifactClock {
    /** {@return the current time in milliseconds (any fixed origin)} */
    long nowMillis();

    /**
     * Blocks until {@link #nowMillis()} reaches {@code deadlineMillis}. Used in threaded mode only:
     * in stepped mode the workspace polls {@link #nowMillis()} instead, so that wake-ups happen at
     * deterministic points.
     */
    void sleepUntil(long deadlineMillis) throws InterruptedException;
}
