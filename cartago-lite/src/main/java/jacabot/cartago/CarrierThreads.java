package jacabot.cartago;

import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The bounded pool of carrier threads of a workspace: at most {@code max} threads, created on
 * demand and ended after 30 s idle; further tasks queue. Daemon threads, so that a forgotten
 * workspace does not keep the JVM alive.
 */
final class CarrierThreads {
    private CarrierThreads() {
    }

    static ThreadPoolExecutor create(String workspace, int max) {
        if (max < 1) {
            throw new IllegalArgumentException("a workspace needs at least one operation thread, not " + max);
        }
        AtomicInteger count = new AtomicInteger();
        ThreadFactory factory = task -> {
            Thread thread = new Thread(task, "cartago-" + workspace + "-op-" + count.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        };
        ThreadPoolExecutor pool = new ThreadPoolExecutor(max, max, 30, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), factory);
        pool.allowCoreThreadTimeOut(true);
        return pool;
    }
}
