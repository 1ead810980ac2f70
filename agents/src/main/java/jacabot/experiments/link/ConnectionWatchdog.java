package jacabot.experiments.link;

import java.util.Collection;
import java.util.concurrent.TimeUnit;

/**
 * Closes connections that take too long to shake hands or to finish a frame, so a client that
 * opens a socket and says nothing (or half a frame) costs a thread for {@link LinkConfig.Guards}'
 * deadlines at most; and has the {@link HandshakeGuard} report failed handshakes. One thread,
 * waking every 50 ms.
 */
final class ConnectionWatchdog extends LinkThread {
    private static final long PERIOD_MS = 50;

    private final LinkConfig.Guards guards;
    private final Collection<RobotConnection> live;
    private final HandshakeGuard handshakes;
    private final long handshakeNanos;
    private final long frameNanos;

    ConnectionWatchdog(LinkConfig.Guards guards, Collection<RobotConnection> live, HandshakeGuard handshakes) {
        super("middleware-watchdog");
        this.guards = guards;
        this.live = live;
        this.handshakes = handshakes;
        this.handshakeNanos = TimeUnit.MILLISECONDS.toNanos(guards.handshakeMs());
        this.frameNanos = TimeUnit.MILLISECONDS.toNanos(guards.frameMs());
    }

    @Override
    long pauseMs() {
        return PERIOD_MS;
    }

    @Override
    void round() {
        long now = System.nanoTime();
        for (RobotConnection c : live) {
            if (c.isClosed()) {
                continue;
            }
            if (!c.handshakeDone() && now - c.startedNanos() > handshakeNanos) {
                c.close("no complete handshake within " + guards.handshakeMs() + " ms");
            }
            long frameStart = c.frameStartNanos();
            if (frameStart != 0 && now - frameStart > frameNanos) {
                c.close("a frame took longer than " + guards.frameMs() + " ms to arrive");
            }
        }
        handshakes.report();
    }
}
