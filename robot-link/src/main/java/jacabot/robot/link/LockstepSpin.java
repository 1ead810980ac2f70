package jacabot.robot.link;

import java.io.IOException;
import java.util.function.LongSupplier;

/**
 * How one end of a lockstep link waits for the other's next frame: a short spin on
 * {@code available()} before the blocking read, for as long as spinning pays.
 *
 * <p>Why: in lockstep the two ends take turns, each waiting some tens of microseconds for the
 * other. A thread blocked in {@code read} lets its core go idle, and on a virtual machine waking an
 * idle core costs about as much as the turn itself ({@code docs/performance-history.md} §3c). A thread
 * that spins keeps its core awake and sees the bytes at once.
 *
 * <p>Why adaptive: spinning only pays while the other end has a core of its own. On a loaded
 * machine the spinner takes the core the other end needs, and the turn takes time slices instead
 * of microseconds. So the budget follows the waits: a wait that ends within it leaves room for
 * twice that wait; a spin that runs out halves it, and below {@link #MIN_BUDGET_NANOS} the end
 * just blocks, trying a spin again only every {@link #PROBE_EVERY} waits.
 *
 * <p>One instance per reading thread; not thread-safe.
 */
public final class LockstepSpin {
    /** The first budget, and the one a probe tries: a few turns of the control step. */
    static final long INITIAL_BUDGET_NANOS = 100_000;
    static final long MAX_BUDGET_NANOS = 200_000;
    static final long MIN_BUDGET_NANOS = 5_000;
    /** Waits between two tries once spinning stopped paying. */
    static final int PROBE_EVERY = 1_000;

    private final LongSupplier nanoTime;
    private long budget = INITIAL_BUDGET_NANOS;
    private int blockedWaits;
    private long spins, caught;

    public LockstepSpin() {
        this(System::nanoTime);
    }

    LockstepSpin(LongSupplier nanoTime) {
        this.nanoTime = nanoTime;
    }

    /** Spins until {@code ready} reports bytes or the budget runs out; the caller then reads (blocking). */
    public void await(Ready ready) throws IOException {
        if (budget == 0) {
            if (++blockedWaits < PROBE_EVERY) {
                return;
            }
            blockedWaits = 0;
            budget = INITIAL_BUDGET_NANOS;
        }
        spins++;
        long start = nanoTime.getAsLong();
        while (!ready.ready()) {
            if (nanoTime.getAsLong() - start > budget) {
                budget = budget / 2 < MIN_BUDGET_NANOS ? 0 : budget / 2;
                return;
            }
            Thread.onSpinWait();
        }
        caught++;
        long waited = nanoTime.getAsLong() - start;
        budget = Math.min(MAX_BUDGET_NANOS, Math.max(budget, 2 * waited));
    }

    /** {@return the current budget in nanoseconds, 0 when the end just blocks} */
    long budgetNanos() {
        return budget;
    }

    /** {@return the waits that spun, and of them those the bytes ended} */
    long[] spinsAndCatches() {
        return new long[] {spins, caught};
    }

    /** Whether bytes can be read without blocking. */
    @FunctionalInterface
    public interface Ready {
        boolean ready() throws IOException;
    }
}
