package jacabot.cartago;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BooleanSupplier;

/**
 * Free-running mode: each operation runs on a carrier of a bounded pool; its steps take the
 * artifact's lock, so steps of one artifact exclude each other while different artifacts run in
 * parallel. A suspended operation keeps its carrier (Java 17 has no continuations), so the pool
 * size bounds the operations in progress; beyond it new operations queue.
 */
final class ThreadedScheduler implements Scheduler {
    private final String workspace;
    private final ThreadPoolExecutor carriers;
    private final int max;
    private final ArtifactClock clock;
    private final CartagoLogger logger;
    private final AtomicBoolean warned = new AtomicBoolean();

    ThreadedScheduler(String workspace, int max, ArtifactClock clock, CartagoLogger logger) {
        this.workspace = workspace;
        this.carriers = CarrierThreads.create(workspace, max);
        this.max = max;
        this.clock = clock;
        this.logger = logger;
    }

    @Override
    public void launch(OpExecution op) {
        if (carriers.getActiveCount() >= max && warned.compareAndSet(false, true)) {
            logger.warning(workspace, "all " + max + " operation threads are busy (operations suspended in await keep"
                    + " theirs); new operations wait for one to end", null);
        }
        carriers.execute(op);
    }

    @Override
    public void enter(OpExecution op, BooleanSupplier ready) throws InterruptedException {
        ReentrantLock lock = op.core().lock();
        lock.lockInterruptibly();
        try {
            while (!ready.getAsBoolean()) {
                op.core().changed().await();
            }
        } catch (InterruptedException | RuntimeException | Error e) {
            lock.unlock();
            throw e;
        }
    }

    @Override
    public void leave(OpExecution op) {
        op.core().changed().signalAll();
        op.core().lock().unlock();
    }

    @Override
    public void sleepUntil(OpExecution op, long deadline) throws InterruptedException {
        clock.sleepUntil(deadline);
    }

    @Override
    public void awaitDone(OpExecution op, CompletableFuture<?> done) throws InterruptedException {
        try {
            done.get();
        } catch (ExecutionException e) {
            // The outcome is read by the caller from the future itself.
        }
    }

    @Override
    public void runBlocking(OpExecution op, IBlockingCmd command) {
        command.exec();
    }

    @Override
    public void finished(OpExecution op) {
    }

    @Override
    public void deliver(Runnable event) {
        event.run();
    }

    @Override
    public void deliverLater(Runnable event) {
        try {
            carriers.execute(event);
        } catch (RejectedExecutionException closed) {
            event.run();
        }
    }

    @Override
    public boolean runInline(OpExecution op) {
        return false;
    }

    @Override
    public int runPending() {
        throw new IllegalStateException("runPending() is for stepped workspaces; workspace " + workspace + " is threaded");
    }

    @Override
    public void close() {
        carriers.shutdownNow();
    }
}
