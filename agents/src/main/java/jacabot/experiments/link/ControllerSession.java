package jacabot.experiments.link;

import jacabot.robot.link.Protocol;
import jacabot.robot.link.Uplink;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * The controller attached to one link: which connection speaks for the robot now (the last one that
 * proved the secret), and what its frames become: {@link LinkEvent}s in the {@link EventQueue},
 * at rebased times ({@link ClockRebase}), and {@code APPLIED} reports for the {@link CommandStream}.
 * Every connection reports here ({@link ConnectionOwner}).
 */
final class ControllerSession implements ConnectionOwner {
    private final Consumer<String> log;
    private final LinkTimings timings;
    private final LinkConfig config;
    private final EventQueue events;
    private final ClockRebase clock;
    private final CommandStream commands;
    private final HandshakeGuard handshakes;
    /** Told when a connection ended or was refused: it is no longer watched. */
    private final Consumer<RobotConnection> ended;
    private final AtomicLong badFrames = new AtomicLong();
    /** The controller that proved the secret last, null while none is connected (changes under this). */
    private volatile RobotConnection current;
    private volatile long simTimeMs = -1;
    private volatile String lastCloseReason;
    private volatile boolean closed;

    ControllerSession(LinkConfig config, LinkTimings timings, EventQueue events, CommandStream commands,
            HandshakeGuard handshakes, Consumer<RobotConnection> ended) {
        this.config = config;
        this.log = config.log();
        this.timings = timings;
        this.events = events;
        this.clock = new ClockRebase(log);
        this.commands = commands;
        this.handshakes = handshakes;
        this.ended = ended;
    }

    RobotConnection current() {
        return current;
    }

    long simTimeMs() {
        return simTimeMs;
    }

    String lastCloseReason() {
        return lastCloseReason;
    }

    long badFrames() {
        return badFrames.get();
    }

    /** Waits until a controller is attached or the link closes; {@return whether one is attached} */
    boolean awaitAttached(long timeout, TimeUnit unit) throws InterruptedException {
        long end = System.nanoTime() + unit.toNanos(timeout);
        synchronized (this) {
            while (current == null && !closed) {
                long left = end - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                TimeUnit.NANOSECONDS.timedWait(this, left);
            }
            return current != null;
        }
    }

    /** The link closes: the current connection too, and nobody waits for one any more. */
    void close(String reason) {
        closed = true;
        RobotConnection c = current;
        if (c != null) {
            c.close(reason);
        }
    }

    /** Wakes those waiting in {@link #awaitAttached} (after {@link #close}). */
    synchronized void wake() {
        notifyAll();
    }

    @Override
    public void attached(RobotConnection c) {
        // only a controller that proved the secret gets here: it may take the robot over
        RobotConnection old;
        synchronized (this) {
            old = current;
            current = c;
            notifyAll();
        }
        if (old != null) {
            old.close("replaced by a new authenticated connection from the controller");
        }
        clock.connected();
        Protocol.Hello h = c.hello();
        log.accept("controller connected: robot '" + h.robotName() + "' of world '" + h.worldName() + "', "
                + (h.lockstep() ? "lockstep" : "real time") + ", control step " + h.controlStepMs() + " ms");
        events.dispatch(new LinkEvent.Connected(h.robotName(), h.worldName(), h.controlStepMs(), h.lockstep()));
    }

    @Override
    public void refused(RobotConnection c, String reason, boolean authentication) {
        ended.accept(c);
        lastCloseReason = reason;
        handshakes.failed(reason);
    }

    @Override
    public void badFrame(RobotConnection c, String reason) {
        long n = badFrames.incrementAndGet();
        if (n <= 20 || n % 1000 == 0) {
            log.accept("bad frame dropped (" + n + " so far): " + reason);
        }
    }

    @Override
    public void frame(RobotConnection c, Uplink frame) {
        if (c != current) {
            return; // a replaced connection's last words
        }
        if (frame instanceof Uplink.Batch) {
            Uplink.Batch b = (Uplink.Batch) frame;
            long received = config.clock().nowMicros();
            long t = clock.rebase(c.hello(), b.simTimeMs());
            simTimeMs = t;
            for (var info : b.readings()) {
                LinkEvent.Reading r = new LinkEvent.Reading(info, b.step(), t, b.sampledMicros(), received);
                timings.received(r);
                events.dispatch(r);
            }
        } else if (frame instanceof Uplink.StepMarker) {
            Uplink.StepMarker m = (Uplink.StepMarker) frame;
            events.dispatch(new LinkEvent.StepMarker(m.step(), clock.rebase(c.hello(), m.simTimeMs()), m.awaitsAck()));
        } else if (frame instanceof Uplink.Applied) {
            commands.applied((Uplink.Applied) frame);
        } else if (frame instanceof Uplink.FailSafe) {
            Uplink.FailSafe f = (Uplink.FailSafe) frame;
            log.accept("the controller's fail-safe stopped the wheels: " + f.reason());
            events.dispatch(new LinkEvent.FailSafe(f.simTimeMs(), f.reason()));
        }
    }

    @Override
    public void detached(RobotConnection c, String reason) {
        ended.accept(c);
        boolean wasCurrent;
        synchronized (this) {
            wasCurrent = current == c;
            if (wasCurrent) {
                current = null;
            }
            notifyAll();
        }
        lastCloseReason = reason;
        log.accept("connection closed: " + reason);
        if (wasCurrent) {
            events.dispatch(new LinkEvent.Disconnected(reason));
        }
    }
}
