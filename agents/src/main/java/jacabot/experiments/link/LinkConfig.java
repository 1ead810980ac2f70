package jacabot.experiments.link;

import jacabot.robot.link.LinkClock;
import jacabot.robot.link.Protocol;
import jacabot.robot.link.SensorInfoFilter;
import java.net.InetAddress;
import java.util.function.Consumer;

/**
 * How a {@link MiddlewareLink} listens. Immutable; start from {@link #defaults()}.
 *
 * @param bindAddress   where the server socket listens: loopback unless the controller runs elsewhere
 * @param port          the port (the thesis' 4444; 0 picks a free one, see {@link MiddlewareLink#port()})
 * @param heartbeatMs   real time: send a heartbeat when no command went out for this long (0: never),
 *                      well under the controller's fail-safe time
 * @param queueCapacity events kept for {@link MiddlewareLink#receive()}; when nobody reads, the oldest
 *                      readings go (a connection event is never dropped)
 * @param limits        the deserialization filter's limits
 * @param clock         the timestamp clock shared with the controller
 * @param log           where connections, refusals and closing reasons are reported
 */
public record LinkConfig(InetAddress bindAddress, int port, long heartbeatMs, int queueCapacity,
                         SensorInfoFilter.Limits limits, LinkClock clock, Consumer<String> log) {
    public LinkConfig {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in 0..65535, got " + port);
        }
        if (heartbeatMs < 0 || queueCapacity < 16) {
            throw new IllegalArgumentException("heartbeatMs must be >= 0 and queueCapacity >= 16");
        }
    }

    /** {@return 127.0.0.1:4444, heartbeat every 250 ms, 4096 queued events, log to stderr} */
    public static LinkConfig defaults() {
        return new LinkConfig(InetAddress.getLoopbackAddress(), Protocol.DEFAULT_PORT, 250, 4096,
                SensorInfoFilter.Limits.DEFAULT, LinkClock.system(), line -> System.err.println("[middleware] " + line));
    }

    public LinkConfig withPort(int newPort) {
        return new LinkConfig(bindAddress, newPort, heartbeatMs, queueCapacity, limits, clock, log);
    }

    public LinkConfig withBindAddress(InetAddress address) {
        return new LinkConfig(address, port, heartbeatMs, queueCapacity, limits, clock, log);
    }

    public LinkConfig withHeartbeatMs(long ms) {
        return new LinkConfig(bindAddress, port, ms, queueCapacity, limits, clock, log);
    }

    public LinkConfig withLimits(SensorInfoFilter.Limits newLimits) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, newLimits, clock, log);
    }

    public LinkConfig withClock(LinkClock newClock) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, newClock, log);
    }

    public LinkConfig withLog(Consumer<String> newLog) {
        return new LinkConfig(bindAddress, port, heartbeatMs, queueCapacity, limits, clock, newLog);
    }
}
