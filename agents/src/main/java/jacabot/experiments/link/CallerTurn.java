package jacabot.experiments.link;

import jacabot.robot.link.LockstepTurn;
import jacabot.robot.link.SensorDataReader;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.net.SocketAddress;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The middleware's side of {@link LockstepTurn}: once {@link #enable enabled}, a lockstep
 * connection's reading thread lends its sensor data stream here after the handshake and waits; the
 * controller's simulation thread, having written a step, reads that step here up to its marker,
 * whose handler answers it, all on the simulation thread. The reading thread takes its stream back
 * when a turn meets the connection's end (it reports that end, as it would have), when the
 * connection is closed from this side, or when the turns are {@link #release released}; it then
 * reads on by itself.
 *
 * <p>A turn serves only the connection its step was written on (named by the controller's end), so
 * it never waits for bytes that went elsewhere: when that connection is not lent within
 * {@link #LEND_WAIT_MS} (its handshake ends a moment after the controller's), the turns are released
 * and every connection reads on its own thread.
 */
final class CallerTurn implements LockstepTurn {
    static final long LEND_WAIT_MS = 5_000;
    /** A wait looks at {@link #released} at least this often: {@link #release} may not get the lock to signal. */
    private static final long RECHECK_NANOS = TimeUnit.MILLISECONDS.toNanos(100);

    private final long lendWaitNanos;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private volatile boolean enabled;
    /** Set without the lock (a turn in progress may hold it: a debugger can pause the agent in it). */
    private volatile boolean released;
    /** The connection whose stream turns read now, or null. */
    private RobotConnection lent;
    /** Connections given back with the end a turn met, for their reading threads to report. */
    private final Map<RobotConnection, String> ended = new IdentityHashMap<>();

    CallerTurn() {
        this(LEND_WAIT_MS);
    }

    /** @param lendWaitMs how long a turn waits for its connection to be lent (tests shorten it) */
    CallerTurn(long lendWaitMs) {
        this.lendWaitNanos = TimeUnit.MILLISECONDS.toNanos(lendWaitMs);
    }

    /** From now on lockstep connections lend their streams; call it before the controller connects. */
    void enable() {
        enabled = true;
    }

    /**
     * The reading thread of lockstep connection {@code c}, after its handshake: lends its stream and
     * waits until it is given back. {@return the end a turn met, or null to read on}
     */
    String lend(RobotConnection c) {
        if (!enabled) {
            return null;
        }
        lock.lock();
        try {
            if (released) {
                return null;
            }
            lent = c; // a connection lent before is replaced: closed, and its thread reads its end itself
            changed.signalAll();
            while (lent == c && !released) {
                try {
                    changed.awaitNanos(RECHECK_NANOS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt(); // the link closes: no turn reads c any more
                    if (lent == c) {
                        lent = null;
                    }
                    break;
                }
            }
            return ended.remove(c);
        } finally {
            lock.unlock();
        }
    }

    /**
     * {@code c} was closed from this side: if lent, its thread takes it back to report the end. A
     * turn in progress (the lock taken) meets that end itself when it reads {@code c}.
     */
    void giveBack(RobotConnection c) {
        if (enabled && lock.tryLock()) {
            try {
                if (lent == c) {
                    lent = null;
                    changed.signalAll();
                }
            } finally {
                lock.unlock();
            }
        }
    }

    @Override
    public boolean take(SocketAddress controller, long step) {
        lock.lock();
        try {
            long deadline = System.nanoTime() + lendWaitNanos;
            while (!released && (lent == null || !controller.equals(lent.remote()))) {
                long wait = deadline - System.nanoTime();
                if (wait <= 0) {
                    releaseLocked(); // its handshake did not end: each end reads on its own thread
                    return false;
                }
                changed.awaitNanos(Math.min(wait, RECHECK_NANOS));
            }
            if (released) {
                return false;
            }
            RobotConnection c = lent;
            String end = readStep(c);
            if (end != null) {
                ended.put(c, end);
                lent = null;
                changed.signalAll();
                return false;
            }
            return true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            releaseLocked();
            return false;
        } finally {
            if (released) {
                releaseLocked(); // released while this turn ran
            }
            lock.unlock();
        }
    }

    /** Does not wait for a turn in progress: that turn gives the stream back as it ends. */
    @Override
    public void release() {
        released = true;
        if (lock.tryLock()) {
            try {
                releaseLocked();
            } finally {
                lock.unlock();
            }
        }
    }

    private void releaseLocked() {
        released = true;
        lent = null;
        changed.signalAll();
    }

    /**
     * Reads {@code c}'s frames up to the step marker and hands them on (its handler answers the
     * step). The step was written whole before the turn, so no read waits long.
     * {@return the connection's end if it came instead, else null}
     */
    private static String readStep(RobotConnection c) {
        SensorDataReader reader = c.reader();
        try {
            while (true) {
                Uplink frame = reader.read();
                String end = c.handle(frame);
                if (end != null) {
                    return end;
                }
                if (frame instanceof Uplink.StepMarker) {
                    return null;
                }
            }
        } catch (IOException | RuntimeException e) {
            return RobotConnection.endReason(e);
        }
    }
}
