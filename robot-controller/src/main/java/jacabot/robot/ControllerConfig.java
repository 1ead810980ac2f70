package jacabot.robot;

import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkSecret;
import jacabot.robot.link.Protocol;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import javax.net.ssl.SSLContext;

/**
 * How a {@link RobotController} runs: where the middleware listens, which robot, the mode, the
 * fail-safe and the link's housekeeping. Immutable; start from {@link #defaults()} and use the
 * {@code with...} methods.
 *
 * @param host             the middleware's address (loopback by default)
 * @param port             the middleware's port
 * @param robotName        the robot to control, null for the world's first robot
 * @param lockstep         lockstep (the world waits for the agent each step) or real time
 * @param speedFactor      real time × this factor (real-time mode only)
 * @param failSafeMs       ms without a command or heartbeat after which the wheels stop, both of wall-clock
 *                         and of simulated time: a world faster than the wall clock is held meanwhile, so
 *                         the robot stops within this plus one control step of simulated time (real-time
 *                         mode; in lockstep the world cannot move without the agent)
 * @param minBackoffMs     first wait before reconnecting; doubles up to {@code maxBackoffMs}
 * @param maxBackoffMs     longest wait between two connection attempts
 * @param resetEvery       reset the ObjectOutputStream every this many batches
 * @param outboxCapacity   batches waiting for the sender thread; in real time the oldest is dropped
 * @param sendCameraImage  also send the whole camera image each step (off: the three sections only)
 * @param clock            the timestamp clock shared with the middleware
 * @param nanoTime         the monotonic clock the fail-safe measures silence with
 * @param log              where the controller reports connections, drops and refused frames
 * @param eventLog         one line per reading, applied command and pose, or null; identical for two
 *                         lockstep runs of the same world and agent
 * @param secret           the key shared with the middleware ({@link LinkSecret}); null: the user's
 *                         secret file, read when the link starts
 * @param tls              null: plain TCP; else TLS with this context's trust store (the JDK's
 *                         {@code SSLSocket}; the middleware's certificate must name the host)
 */
public record ControllerConfig(String host, int port, String robotName, boolean lockstep, double speedFactor,
                               long failSafeMs, long minBackoffMs, long maxBackoffMs, int resetEvery, int outboxCapacity,
                               boolean sendCameraImage, LinkClock clock, LongSupplier nanoTime, Consumer<String> log,
                               Consumer<String> eventLog, LinkSecret secret, SSLContext tls) {
    public ControllerConfig {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be in 0..65535, got " + port);
        }
        if (!(speedFactor > 0) || Double.isInfinite(speedFactor)) {
            throw new IllegalArgumentException("speed factor must be a positive number, got " + speedFactor);
        }
        if (failSafeMs <= 0 || minBackoffMs <= 0 || maxBackoffMs < minBackoffMs || resetEvery < 1 || outboxCapacity < 2) {
            throw new IllegalArgumentException("invalid link timing: failSafeMs=" + failSafeMs + ", backoff "
                    + minBackoffMs + ".." + maxBackoffMs + " ms, resetEvery=" + resetEvery + ", outbox=" + outboxCapacity);
        }
    }

    /** The default fail-safe: with a 40 ms control step the robot stops within 190 ms of a silence. */
    public static final long FAIL_SAFE_MS = 150;

    /** {@return 127.0.0.1:4444, first robot, real time × 1, fail-safe 150 ms, back-off 100 ms..2 s, log to stderr} */
    public static ControllerConfig defaults() {
        return new ControllerConfig(Protocol.DEFAULT_HOST, Protocol.DEFAULT_PORT, null, false, 1.0, FAIL_SAFE_MS, 100, 2000, 100,
                64, false, LinkClock.system(), System::nanoTime, line -> System.err.println("[controller] " + line), null, null, null);
    }

    public ControllerConfig withAddress(String newHost, int newPort) {
        return new ControllerConfig(newHost, newPort, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs,
                maxBackoffMs, resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withRobot(String name) {
        return new ControllerConfig(host, port, name, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withLockstep(boolean on) {
        return new ControllerConfig(host, port, robotName, on, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withSpeedFactor(double factor) {
        return new ControllerConfig(host, port, robotName, lockstep, factor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withFailSafeMs(long ms) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, ms, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withBackoff(long minMs, long maxMs) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minMs, maxMs, resetEvery,
                outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withResetEvery(int batches) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                batches, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withCameraImage(boolean on) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, on, clock, nanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withClocks(LinkClock newClock, LongSupplier newNanoTime) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, newClock, newNanoTime, log, eventLog, secret, tls);
    }

    public ControllerConfig withLog(Consumer<String> newLog) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, newLog, eventLog, secret, tls);
    }

    /** {@return this config with the key shared with the middleware} */
    public ControllerConfig withSecret(LinkSecret newSecret) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, newSecret, tls);
    }

    /** Connects with TLS, trusting what {@code context} trusts. */
    public ControllerConfig withTls(SSLContext context) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, eventLog, secret, context);
    }

    /** {@return the configured secret, else the user's secret file's} */
    @Override
    public LinkSecret secret() {
        return secret != null ? secret : LinkSecret.userDefault();
    }

    public ControllerConfig withEventLog(Consumer<String> newEventLog) {
        return new ControllerConfig(host, port, robotName, lockstep, speedFactor, failSafeMs, minBackoffMs, maxBackoffMs,
                resetEvery, outboxCapacity, sendCameraImage, clock, nanoTime, log, newEventLog, secret, tls);
    }
}
