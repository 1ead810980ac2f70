package jacabot.robot;

import jacabot.robot.link.CommandCode;
import jacabot.robot.link.ReceivedCommand;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * Where the receiver thread leaves commands for the simulation thread. Its monitor is the world
 * object: the simulation thread calls the controller while holding the world's lock (SimRunner),
 * so waiting here for the agent's acknowledgement releases the world to the viewer meanwhile.
 */
final class CommandInbox {
    /** How a lockstep wait for {@code STEP_ACK(step)} ended. */
    enum AckResult { ACKED, DROPPED, CLOSED }

    /** What arrived since the last drain: the commands, and whether the link dropped meanwhile. */
    record Drained(List<ReceivedCommand> commands, boolean dropped) {
    }

    private final Object lock;
    private final LongSupplier nanoTime;
    private final List<ReceivedCommand> commands = new ArrayList<>();
    private long ackedStep = -1;
    private boolean connected, dropped, closed;
    private long lastHeardNanos;
    private long connections;
    private Consumer<ReceivedCommand> onReceipt;

    CommandInbox(Object lock, LongSupplier nanoTime) {
        this.lock = lock;
        this.nanoTime = nanoTime;
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
            lastHeardNanos = nanoTime.getAsLong();
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
                lastHeardNanos = nanoTime.getAsLong();
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

    /** {@return wall-clock nanoseconds since the last command or heartbeat} */
    long silenceNanos() {
        synchronized (lock) {
            return nanoTime.getAsLong() - lastHeardNanos;
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

    /** Lockstep: takes the commands of the acknowledged step. */
    List<ReceivedCommand> takeCommands() {
        synchronized (lock) {
            List<ReceivedCommand> out = new ArrayList<>(commands);
            commands.clear();
            return out;
        }
    }
}
