package jacabot.app.inspector;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * One agent's recent past for the inspector's time slider: a ring of frames (a mind state and,
 * for a robot, its body) and a ring of plan selections. Bounded, so a long run keeps its last
 * {@code capacity} frames only. A frame is kept when the mind changed, or at least every
 * {@link #KEEP_EVERY_MS} of the agent's time so the robot's motion shows too. Thread-safe: the
 * agent's thread records, the web server's threads read.
 */
public final class MindHistory {
    /** Without a change of mind, a frame is still kept this often (agent's clock, ms). */
    static final long KEEP_EVERY_MS = 250;

    /** A mind and its robot (null for an agent without a body) at one instant; {@code index} counts from the start. */
    public record Frame(long index, MindState mind, RobotView robot) {
    }

    private final String agent;
    private final int capacity;
    private final ArrayDeque<Frame> frames = new ArrayDeque<>();
    private final ArrayDeque<MindState.Selection> selections = new ArrayDeque<>();
    private List<String> plans = List.of();
    private long next;
    private Frame latest;
    private long version;

    public MindHistory(String agent, int capacity) {
        this.agent = agent;
        this.capacity = capacity;
    }

    public String agent() {
        return agent;
    }

    /** Records a state; it becomes the latest frame, and a kept one if the mind changed or time passed. */
    public synchronized void record(MindState mind, RobotView robot, List<String> planLibrary) {
        plans = planLibrary;
        for (MindState.Selection s : mind.selections()) {
            if (selections.size() >= capacity) {
                selections.removeFirst();
            }
            selections.addLast(s);
        }
        Frame last = frames.peekLast();
        boolean keep = last == null || !mind.sameMind(last.mind()) || mind.timeMs() - last.mind().timeMs() >= KEEP_EVERY_MS;
        if (keep) {
            latest = new Frame(next++, mind, robot);
            if (frames.size() >= capacity) {
                frames.removeFirst();
            }
            frames.addLast(latest);
            version++;
            notifyAll();
        }
    }

    /** {@return a change counter: it grows with every kept frame} */
    public synchronized long version() {
        return version;
    }

    /** Waits up to {@code millis} for a version after {@code seen}. {@return the version now} */
    public synchronized long awaitChange(long seen, long millis) throws InterruptedException {
        long end = System.currentTimeMillis() + millis;
        while (version == seen) {
            long left = end - System.currentTimeMillis();
            if (left <= 0) {
                break;
            }
            wait(left);
        }
        return version;
    }

    public synchronized Frame latest() {
        return latest;
    }

    /** {@return the frame with this index, or the nearest one still kept; null before any} */
    public synchronized Frame frame(long index) {
        Frame best = null;
        for (Frame f : frames) {
            if (best == null || Math.abs(f.index() - index) < Math.abs(best.index() - index)) {
                best = f;
            }
        }
        return best;
    }

    /** {@return the kept frames' indices and times, for the slider} */
    public synchronized List<long[]> timeline() {
        var out = new ArrayList<long[]>(frames.size());
        frames.forEach(f -> out.add(new long[] {f.index(), f.mind().timeMs()}));
        return out;
    }

    public synchronized List<MindState.Selection> selections() {
        return new ArrayList<>(selections);
    }

    public synchronized List<String> plans() {
        return plans;
    }
}
