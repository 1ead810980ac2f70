package jacabot.experiments.link;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * Counts failed handshakes (wrong secret, garbage, timeout) and limits what they may cost: past
 * {@code failedPerSecond} failures in a second, and while {@code pendingHandshakes} connections are
 * shaking hands, a new connection is closed unheard. The first five failures are logged one by one,
 * then at most one summary line a second. Recovery, not in the thesis: the thesis' link trusts the
 * first connection.
 */
final class HandshakeGuard {
    private final LinkConfig.Guards guards;
    private final Consumer<String> log;
    /** Every failed handshake, those refused unheard included. */
    private final AtomicLong failed = new AtomicLong();
    /** This second's failures, the second they count in, and the connections refused unheard (all under this). */
    private long failedThisSecond, failureSecond, rateLimited;
    /** Failures logged so far (one by one or in a summary), and the second of the last summary. */
    private volatile long loggedFailures;
    private long lastSummarySecond = -1;

    HandshakeGuard(LinkConfig.Guards guards, Consumer<String> log) {
        this.guards = guards;
        this.log = log;
    }

    long failedHandshakes() {
        return failed.get();
    }

    /** {@return why a new connection is closed unheard (rate limit, too many handshakes), or null} */
    String refuseAtOnce(LongSupplier pendingHandshakes) {
        long second = System.nanoTime() / 1_000_000_000L;
        synchronized (this) {
            if (second == failureSecond && failedThisSecond >= guards.failedPerSecond()) {
                rateLimited++;
                failed.incrementAndGet();
                return "rate-limited";
            }
        }
        if (pendingHandshakes.getAsLong() >= guards.pendingHandshakes()) {
            failed.incrementAndGet();
            return "too many handshakes at once";
        }
        return null;
    }

    /** A handshake failed: counted in this second, and logged if among the first five. */
    void failed(String reason) {
        long n = failed.incrementAndGet();
        long second = System.nanoTime() / 1_000_000_000L;
        synchronized (this) {
            if (second != failureSecond) {
                failureSecond = second;
                failedThisSecond = 0;
            }
            failedThisSecond++;
        }
        if (n <= 5) {
            loggedFailures = n;
            log.accept("refused a connection: " + reason);
        }
    }

    /** Logs the failures not logged yet, at most once a second (the watchdog calls this). */
    void report() {
        long n = failed.get();
        long second = System.nanoTime() / 1_000_000_000L;
        if (n > loggedFailures && second != lastSummarySecond) {
            long limited;
            synchronized (this) {
                limited = rateLimited;
            }
            log.accept((n - loggedFailures) + " more failed connection attempts (" + limited
                    + " refused unheard by the rate limit so far)");
            loggedFailures = n;
            lastSummarySecond = second;
        }
    }
}
