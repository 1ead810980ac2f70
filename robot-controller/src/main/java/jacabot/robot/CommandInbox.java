package jacabot.robot;

import jacabot.robot.link.CommandCode;
import jacabot.robot.link.ReceivedCommand;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * Where the link leaves commands for the simulation thread: the receiver thread in real time, the
 * simulation thread itself in lockstep (it reads the answer to its step). Its monitor is the world
 * object, so a command is taken between two physics steps.
 */
final class CommandInbox {
    /** How a lockstep wait for {@code STEP_ACK(step)} ended. */
    enum AckResult { ACKED, DROPPED, CLOSED }

    /** What arrived since the last drain: the commands, and whether the link dropped meanwhile. */
    record Drained(List<ReceivedCommand> commands, boolean dropped) {
    }

    /** How long nothing has come from the agent side, in wall-clock and in simulated milliseconds. */
    record Silence(long wallMs, long simMs) {
    }

    private final Object lock;
    private final LongSupplier nanoTime;
    private final LongSupplier simTimeMs;
    private final List<ReceivedCommand> commands = new ArrayList<>();
    private long ackedStep = -1;
    private boolean connected, dropped, closed;
    private long lastHeardNanos, lastHeardSimMs;
    private long connections;
    private Consumer<ReceivedCommand> onReceipt;

    /** @param simTimeMs the world's time; read with {@code lock} held, so between two world steps */
    CommandInbox(Object lock, LongSupplier nanoTime, LongSupplier simTimeMs) {
        this.lock = lock;
        this.nanoTime = nanoTime;
        this.simTimeMs = simTimeMs;
    }

    /** {@return the world's time when the middleware was last heard from (a command or a heartbeat)} */
    long lastHeardSimMs() {
        synchronized (lock) {
            return lastHeardSimMs;
        }
    }

    private void heard() {
        lastHeardNanos = nanoTime.getAsLong();
        lastHeardSimMs = simTimeMs.getAsLong();
    }

    /**
     * Real time: commands go to {@code action} on the receiver thread as they arrive, with the
     * world's lock held (so between two physics steps), instead of waiting for the next control step.
     */
    void applyOnReceipt(Consumer<ReceivedCommand> action) {
        synchronized (lock) {
            onReceipt = action;
        }
    }

    /** Receiver thread: a valid command arrived (a heartbeat only refreshes the silence timer). */
    void offer(ReceivedCommand rc) {
        synchronized (lock) {
            heard();
            CommandCode code = rc.command().code();
            if (code == CommandCode.STEP_ACK) {
                ackedStep = Math.max(ackedStep, (long) rc.command().arg(0));
                lock.notifyAll();
            } else if (code != CommandCode.HEARTBEAT) {
                if (onReceipt != null && connected) {
                    onReceipt.accept(rc);
                } else {
                    commands.add(rc);
                }
            }
        }
    }

    /** Receiver thread: the connection came up or went down. */
    void connectionChanged(boolean up) {
        synchronized (lock) {
            connected = up;
            if (up) {
                connections++;
                heard();
            } else {
                dropped = true;
                commands.clear(); // half a step's commands must not be mistaken for a whole one
            }
            lock.notifyAll();
        }
    }

    /** The controller is shutting down: every wait returns. */
    void close() {
        synchronized (lock) {
            closed = true;
            lock.notifyAll();
        }
    }

    boolean isConnected() {
        synchronized (lock) {
            return connected;
        }
    }

    /** {@return how many connections have come up so far} */
    long connections() {
        synchronized (lock) {
            return connections;
        }
    }

    /**
     * Real time, simulation thread, world lock held: the silence that trips a fail-safe of
     * {@code limitMs}, or null. It trips once the agent side has been silent for {@code limitMs} of
     * wall-clock time and of simulated time. When the world ran faster than the wall clock (a speed
     * factor, or a runner catching up after a pause) and the robot is moving, the world is held here
     * (its lock released) until a word comes or the wall clock catches up: so the robot never drives
     * more than {@code limitMs} of simulated time, plus one control step, on a word that is not renewed.
     */
    Silence awaitSilence(long limitMs, boolean moving) throws InterruptedException {
        synchronized (lock) {
            while (connected && !closed) {
                long wallMs = TimeUnit.NANOSECONDS.toMillis(nanoTime.getAsLong() - lastHeardNanos);
                long simMs = simTimeMs.getAsLong() - lastHeardSimMs;
                if (wallMs >= limitMs && simMs >= limitMs || wallMs >= limitMs && !moving) {
                    return new Silence(wallMs, simMs);
                }
                if (simMs < limitMs || !moving) {
                    return null;
                }
                lock.wait(Math.max(1, Math.min(10, limitMs - wallMs)));
            }
            return null;
        }
    }

    /** Real time: takes everything that arrived, and whether the link dropped since the last call. */
    Drained drain() {
        synchronized (lock) {
            Drained d = new Drained(new ArrayList<>(commands), dropped);
            commands.clear();
            dropped = false;
            return d;
        }
    }

    /** Lockstep: waits until a connection is up; {@return false when closed instead} */
    boolean awaitConnected() throws InterruptedException {
        synchronized (lock) {
            while (!connected && !closed) {
                lock.wait();
            }
            dropped = false;
            return !closed;
        }
    }

    /** Lockstep: waits for {@code STEP_ACK(step)}, a drop or the end. */
    AckResult awaitAck(long step) throws InterruptedException {
        synchronized (lock) {
            while (true) {
                if (closed) {
                    return AckResult.CLOSED;
                }
                if (dropped) {
                    dropped = false;
                    return AckResult.DROPPED;
                }
                if (ackedStep >= step) {
                    return AckResult.ACKED;
                }
                lock.wait();
            }
        }
    }

    /** {@return whether {@code STEP_ACK(step)} has come} */
    boolean hasAck(long step) {
        synchronized (lock) {
            return ackedStep >= step;
        }
    }

    /** Lockstep: takes the commands of the acknowledged step. */
    List<ReceivedCommand> takeCommands() {
        synchronized (lock) {
            List<ReceivedCommand> out = new ArrayList<>(commands);
            commands.clear();
            return out;
        }
    }
}
