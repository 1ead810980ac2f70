package jacabot.cartago;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.Semaphore;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;

/**
 * Deterministic mode: steps run one at a time, only inside {@link #runPending()}, whose caller
 * waits while a step runs; there is a single <em>turn</em> that passes from the caller to one
 * carrier and back at the step's end (an {@code await*} or the operation's completion). Events and
 * completions are queued and delivered on the caller's thread after each step.
 *
 * <p>Waiting steps are kept with an ordering key and a sequence number: a new operation or a
 * guard wait is keyed by the clock time at which it was queued, an {@code await_time} by its
 * deadline. {@code runPending} repeatedly runs the first step, by (key, sequence), that is ready
 * (guard true, deadline reached), so with a {@link SimulatedClock} and the same calls a run
 * repeats exactly. Blocking commands run outside any turn; their continuation queues when the
 * command returns, which is as (non)deterministic as the I/O itself.
 */
final class SteppedScheduler implements Scheduler {
    private static final Comparator<Waiter> ORDER = Comparator.comparingLong(Waiter::key).thenComparingLong(Waiter::seq);

    /**
     * A step waiting for its turn; {@code launch} steps start a new operation on a carrier, or on
     * the runner's own thread when it never waits ({@code here}).
     */
    private record Waiter(long key, long seq, OpExecution op, BooleanSupplier ready, boolean underLock, boolean launch,
                          boolean here) {
    }

    private final String workspace;
    private final ThreadPoolExecutor carriers;
    private final int max;
    private final ArtifactClock clock;
    private final CartagoLogger logger;
    /** Released by a carrier when it gives the turn back to the runner. */
    private final Semaphore returned = new Semaphore(0);
    private final List<Waiter> waiting = new ArrayList<>();
    private final Deque<Runnable> outbox = new ArrayDeque<>();
    private long seq;
    private int live;
    private Thread runner;
    private boolean warned;

    SteppedScheduler(String workspace, int max, ArtifactClock clock, CartagoLogger logger) {
        this.workspace = workspace;
        this.carriers = CarrierThreads.create(workspace, max);
        this.max = max;
        this.clock = clock;
        this.logger = logger;
    }

    @Override
    public synchronized void launch(OpExecution op) {
        waiting.add(new Waiter(clock.nowMillis(), seq++, op, () -> true, false, true, op.neverWaits()));
    }

    @Override
    public void enter(OpExecution op, BooleanSupplier ready) throws InterruptedException {
        if (op.slot.turn) {
            ReentrantLock lock = op.core().lock();
            lock.lock();
            if (ready.getAsBoolean()) {
                return;
            }
            lock.unlock();
        }
        if (op.slot.inline) {
            throw new IllegalStateException("operation " + op.describe() + " runs inline and cannot wait for its guard");
        }
        awaitTurn(op, clock.nowMillis(), ready, true);
        op.core().lock().lock();
    }

    @Override
    public void leave(OpExecution op) {
        op.core().lock().unlock();
    }

    @Override
    public void sleepUntil(OpExecution op, long deadline) throws InterruptedException {
        awaitTurn(op, deadline, () -> clock.nowMillis() >= deadline, false);
    }

    @Override
    public void awaitDone(OpExecution op, CompletableFuture<?> done) throws InterruptedException {
        awaitTurn(op, clock.nowMillis(), done::isDone, false);
    }

    @Override
    public void runBlocking(OpExecution op, IBlockingCmd command) {
        op.slot.outside = true;
        giveTurnBack(op);
        command.exec();
    }

    @Override
    public void finished(OpExecution op) {
        if (op.slot.inline) {
            op.slot.turn = false; // the caller's own turn: nobody waits for it back
            return;
        }
        synchronized (this) {
            live--;
        }
        if (op.slot.turn) {
            giveTurnBack(op);
        }
    }

    @Override
    public synchronized void deliver(Runnable event) {
        outbox.add(event);
    }

    @Override
    public void deliverLater(Runnable event) {
        deliver(event);
    }

    @Override
    public boolean runInline(OpExecution op) {
        List<Waiter> candidates;
        synchronized (this) {
            if (runner != null) {
                throw new IllegalStateException("an operation of workspace " + workspace + " cannot run inline during runPending()");
            }
            if (!outbox.isEmpty()) {
                return false;
            }
            candidates = new ArrayList<>(waiting);
        }
        for (Waiter w : candidates) {
            if (w.launch() || isReady(w)) {
                return false; // it would run first
            }
        }
        runHere(op);
        return true;
    }

    /** Runs an operation to its end on the calling thread, which holds the turn meanwhile (it may not wait). */
    private static void runHere(OpExecution op) {
        op.slot.inline = true;
        op.slot.turn = true;
        op.run();
    }

    @Override
    public int runPending() {
        synchronized (this) {
            if (runner != null) {
                throw new IllegalStateException("runPending() of workspace " + workspace + " is already running on "
                        + runner.getName() + "; it is not reentrant");
            }
            runner = Thread.currentThread();
        }
        try {
            int steps = 0;
            for (Waiter next = drainAndPick(); next != null; next = drainAndPick()) {
                if (next.here()) {
                    runHere(next.op()); // the runner would only wait for a carrier: two thread wake-ups saved
                } else {
                    grant(next);
                    returned.acquireUninterruptibly();
                }
                steps++;
            }
            return steps;
        } finally {
            synchronized (this) {
                runner = null;
            }
        }
    }

    @Override
    public void close() {
        carriers.shutdownNow();
    }

    /** Queues the carrier's step, gives the turn back if it has it, and waits to be granted. */
    private void awaitTurn(OpExecution op, long key, BooleanSupplier ready, boolean underLock) throws InterruptedException {
        Waiter waiter;
        synchronized (this) {
            op.slot.outside = false;
            waiter = new Waiter(key, seq++, op, ready, underLock, false, false);
            waiting.add(waiter);
        }
        if (op.slot.turn) {
            giveTurnBack(op);
        }
        try {
            op.slot.grant.acquire();
        } catch (InterruptedException e) {
            synchronized (this) {
                if (waiting.remove(waiter)) {
                    throw e;
                }
            }
            // Granted just as we were interrupted: the runner waits for this step, so take the turn.
            op.slot.grant.acquireUninterruptibly();
            Thread.currentThread().interrupt();
        }
        op.slot.turn = true;
    }

    private void giveTurnBack(OpExecution op) {
        op.slot.turn = false;
        returned.release();
    }

    private void grant(Waiter waiter) {
        if (!waiter.launch()) {
            waiter.op().slot.grant.release();
            return;
        }
        waiter.op().slot.turn = true;
        try {
            carriers.execute(waiter.op());
        } catch (RejectedExecutionException closed) {
            synchronized (this) {
                live--;
            }
            waiter.op().slot.turn = false;
            returned.release();
        }
    }

    /** Delivers the queued events, then {@return the first ready step, removed from the queue, or null} */
    private Waiter drainAndPick() {
        drain();
        List<Waiter> candidates;
        synchronized (this) {
            candidates = new ArrayList<>(waiting);
        }
        candidates.sort(ORDER);
        for (Waiter w : candidates) {
            if (w.launch() && !w.here() && !reserveCarrier()) {
                continue;
            }
            if (w.launch() || isReady(w)) {
                synchronized (this) {
                    waiting.remove(w);
                }
                return w;
            }
        }
        return null;
    }

    private synchronized boolean reserveCarrier() {
        if (live >= max) {
            if (!warned) {
                warned = true;
                logger.warning(workspace, "all " + max + " operation threads are in use by suspended operations;"
                        + " new operations wait", null);
            }
            return false;
        }
        live++;
        return true;
    }

    private boolean isReady(Waiter w) {
        if (!w.underLock()) {
            return w.ready().getAsBoolean();
        }
        ReentrantLock lock = w.op().core().lock();
        lock.lock();
        try {
            return w.ready().getAsBoolean();
        } finally {
            lock.unlock();
        }
    }

    private void drain() {
        while (true) {
            Runnable event;
            synchronized (this) {
                event = outbox.poll();
            }
            if (event == null) {
                return;
            }
            event.run();
        }
    }
}
