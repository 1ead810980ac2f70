package jacabot.experiments.link;

import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorInfoFilter;
import java.net.InetAddress;
import java.util.function.Consumer;
import javax.net.ssl.SSLContext;

/**
 * How a {@link MiddlewareLink} listens. Immutable; start from {@link #defaults()}.
 *
 * @param bindAddress   where the server socket listens: loopback unless the controller runs elsewhere
 * @param port          the port (the thesis' 4444; 0 picks a free one, see {@link MiddlewareLink#port()})
 * @param heartbeatMs   real time: send a heartbeat when no command went out for this long (0: never),
 *                      well under the controller's fail-safe time, and only while the agent reasons
 *                      ({@link MiddlewareLink#setLiveness})
 * @param queueCapacity events kept for {@link MiddlewareLink#receive()}; when nobody reads, the oldest
 *                      readings go (a connection event is never dropped)
 * @param limits        the sensor data stream's limits (array lengths, bytes per reading and batch)
 * @param clock         the timestamp clock shared with the controller
 * @param log           where connections, refusals and closing reasons are reported
 * @param secret        the key shared with the controller; null: the user's secret file
 * @param guards        deadlines and counts that bound what one connection may cost
 * @param tls           null: plain TCP (loopback); else TLS with this context's key (the JDK's
 *                      {@code SSLServerSocket}), for a controller on another machine
 */
public record LinkConfig(InetAddress bindAddress, int port, long heartbeatMs, int queueCapacity,
                         SensorInfoFilter.Limits limits, LinkClock clock, Consumer<String> log, LinkSecret secret,
                         Guards guards, SSLContext tls) {
    /**
     * @param handshakeMs        a connection must finish its handshake within this (wall) time
     * @param frameMs            a frame, once begun, must be complete within this time
     * @param maxBadFrames       malformed readings tolerated per connection before it is closed
     * @param failedPerSecond    failed handshakes per second after which new connections are refused
     *                           at once for the rest of the second
     * @param pendingHandshakes  connections allowed to be shaking hands at once
     */
    public record Guards(long handshakeMs, long frameMs, int maxBadFrames, int failedPerSecond, int pendingHandshakes) {
        public static final Guards DEFAULT = new Guards(2000, 2000, 10, 20, 8);

        public Guards {
            if (handshakeMs <= 0 || frameMs <= 0 || maxBadFrames < 0 || failedPerSecond < 1 || pendingHandshakes < 1) {
                throw new IllegalArgumentException("invalid link guards " + this);
            }
        }
    }

    public LinkConfig {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in 0..65535, got " + port);
        }
        if (heartbeatMs < 0 || queueCapacity < 16) {
            throw new IllegalArgumentException("heartbeatMs must be >= 0 and queueCapacity >= 16");
        }
    }

    /** {@return 127.0.0.1:4444, heartbeat every 50 ms, 4096 queued events, log to stderr, the user's secret} */
    public static LinkConfig defaults() {
        return new LinkConfig(InetAddress.getLoopbackAddress(), Protocol.DEFAULT_PORT, 50, 4096,
                SensorInfoFilter.Limits.DEFAULT, LinkClock.system(), line -> System.err.println("[middleware] " + line),
                null, Guards.DEFAULT, null);
    }

    /** {@return the configured secret, else the user's secret file's} */
    @Override
    public LinkSecret secret() {
        return secret != null ? secret : LinkSecret.userDefault();
    }

    public LinkConfig withPort(int newPort) {
        return new LinkConfig(bindAddress, newPort, heartbeatMs, queueCapacity, limits, clock, log, secret, guards, tls);
    }

    public LinkConfig withBindAddress(InetAddress address) {
        return new LinkConfig(address, port, heartbeatMs, queueCapacity, limits, clock, log, secret, guards, tls);
    }

    public LinkConfig withHeartbeatMs(long ms) {
        return new LinkConfig(bindAddress, port, ms, queueCapacity, limits, clock, log, secret, guards, tls);
    }

    public LinkConfig withLimits(SensorInfoFilter.Limits newLimits) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, newLimits, clock, log, secret, guards, tls);
    }

    public LinkConfig withLog(Consumer<String> newLog) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, clock, newLog, secret, guards, tls);
    }

    public LinkConfig withSecret(LinkSecret newSecret) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, clock, log, newSecret, guards, tls);
    }

    /** Listens with TLS (the context holds the middleware's key and certificate). */
    public LinkConfig withTls(SSLContext context) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, clock, log, secret, guards, context);
    }

    public LinkConfig withGuards(Guards newGuards) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, clock, log, secret, newGuards, tls);
    }
}
