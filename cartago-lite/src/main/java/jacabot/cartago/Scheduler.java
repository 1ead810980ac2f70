package jacabot.cartago;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Semaphore;
import java.util.function.BooleanSupplier;

/**
 * Decides when operation steps run; one per workspace. {@link ThreadedScheduler} lets carriers
 * run in parallel, one step per artifact at a time; {@link SteppedScheduler} runs one step at a
 * time, in a reproducible order, while the caller of {@link Workspace#runPending()} waits.
 * The artifact's state is only touched between {@link #enter} and {@link #leave}.
 */
interface Scheduler {
    /** The scheduler's private state per execution (the stepped scheduler's turn). */
    final class Slot {
        final Semaphore grant = new Semaphore(0);
        /** Whether the execution has the stepped scheduler's single turn. */
        volatile boolean turn;
        /** Whether the execution is running a blocking command outside any turn. */
        volatile boolean outside;
        /** Whether the execution runs on its caller's thread and may therefore not wait. */
        volatile boolean inline;
    }

    /** Starts {@code op} on a carrier (now or later); it calls {@link #finished} at its end. */
    void launch(OpExecution op);

    /**
     * Blocks the carrier until it holds {@code op}'s artifact and {@code ready} holds (evaluated
     * while holding the artifact).
     */
    void enter(OpExecution op, BooleanSupplier ready) throws InterruptedException;

    /** Releases the artifact after the step has committed (or rolled back). */
    void leave(OpExecution op);

    /** Blocks the carrier, which does not hold its artifact, until the clock reaches {@code deadline}. */
    void sleepUntil(OpExecution op, long deadline) throws InterruptedException;

    /** Blocks the carrier, which does not hold its artifact, until {@code done} completes. */
    void awaitDone(OpExecution op, CompletableFuture<?> done) throws InterruptedException;

    /** Runs a blocking command for the carrier, which does not hold its artifact. */
    void runBlocking(OpExecution op, IBlockingCmd command);

    /** The carrier has completed {@code op}. */
    void finished(OpExecution op);

    /** Delivers an event or completion to observers/callers, in order. */
    void deliver(Runnable event);

    /** Delivers later, never on the calling thread (for failures found before an operation starts). */
    void deliverLater(Runnable event);

    /**
     * Stepped mode: runs {@code op} to its end on the calling thread if it would be the next step
     * anyway (nothing else is ready or waiting to be delivered); {@return false, doing nothing,
     * otherwise, and in threaded mode}
     */
    boolean runInline(OpExecution op);

    /** Runs the pending steps (stepped mode); {@return how many ran} */
    int runPending();

    /** Stops the carriers (interrupting waits) and refuses new operations. */
    void close();
}
