package jacabot.experiments.link;

import jacabot.robot.link.Command;
import jacabot.robot.link.LinkClock;
import jacabot.robot.link.LinkCosts;
import jacabot.robot.link.Uplink;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The command stream to the controller (protocol §3): each command's sequence number, the writes,
 * and each robot command kept until the controller's {@code APPLIED} report, which gives its
 * response time (thesis Chapter 5 §3) and, in lockstep, how many steps late it was applied.
 */
final class CommandStream {
    /** Robot commands remembered at most: those whose {@code APPLIED} report never came are forgotten. */
    private static final int PENDING_RESPONSES = 10_000;

    /** A robot command on its way: when the agent's action sent it, and the lockstep step it answered (or −1). */
    private record Sent(long actionMicros, long step) {
    }

    private final LinkClock clock;
    private final LinkTimings timings;
    private final LinkCosts costs;
    private final AtomicInteger seq = new AtomicInteger();
    private final Map<Integer, Sent> inFlight = new LinkedHashMap<>(16, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<Integer, Sent> eldest) {
            return size() > PENDING_RESPONSES;
        }
    };
    /** When the last write went out (the heartbeat fills silences). */
    private volatile long lastSentNanos = System.nanoTime();

    CommandStream(LinkClock clock, LinkTimings timings, LinkCosts costs) {
        this.clock = clock;
        this.timings = timings;
        this.costs = costs;
    }

    long lastSentNanos() {
        return lastSentNanos;
    }

    /** Sends one command; {@return false when {@code c} is null or the write failed (then it is closed)} */
    boolean send(RobotConnection c, Command command, long actionMicros) {
        if (c == null) {
            return false;
        }
        int n = number(command, actionMicros, -1);
        try {
            c.send(n, clock.nowMicros(), command);
            lastSentNanos = System.nanoTime();
            return true;
        } catch (IOException e) {
            c.close("cannot send " + command + ": " + e.getMessage());
            return false;
        }
    }

    /** Lockstep: a step's commands and its {@code STEP_ACK} in one write, so the controller wakes once per step. */
    boolean answerStep(RobotConnection c, List<Command> commands, long step) {
        if (c == null) {
            return false;
        }
        long now = clock.nowMicros();
        List<Command> frames = new ArrayList<>(commands);
        frames.add(Command.stepAck(step));
        int[] seqs = new int[frames.size()];
        for (int i = 0; i < frames.size(); i++) {
            seqs[i] = number(frames.get(i), now, step);
        }
        try {
            long t0 = System.nanoTime();
            c.send(seqs, now, frames);
            lastSentNanos = System.nanoTime();
            costs.addWriting(lastSentNanos - t0);
            return true;
        } catch (IOException e) {
            c.close("cannot send the answer to step " + step + ": " + e.getMessage());
            return false;
        }
    }

    /** The controller applied a command: its response time, and in lockstep how many steps it was late. */
    void applied(Uplink.Applied a) {
        Sent sent;
        synchronized (inFlight) {
            sent = inFlight.remove(a.seq());
        }
        if (sent != null) {
            timings.applied(sent.actionMicros(), a.appliedMicros());
            if (sent.step() >= 0) {
                timings.appliedSteps(a.step() - sent.step());
            }
        }
    }

    /** {@return the next sequence number}; a robot command is remembered until its {@code APPLIED} report. */
    private int number(Command command, long actionMicros, long step) {
        int n = seq.incrementAndGet();
        if (command.code().isRobotCommand()) {
            synchronized (inFlight) {
                inFlight.put(n, new Sent(actionMicros, step));
            }
        }
        return n;
    }
}
