package jacabot.app.inspector;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * One agent's past for the inspector's time slider. The recent frames (a mind state and, for a
 * robot, its body and the world's movable objects) and plan selections stay in bounded rings;
 * anything older is read from the {@link MindArchive} (the run's step log on disk) when asked
 * for, so a long run's history reaches its start with a flat heap. A frame is kept when the mind
 * changed, or at least every {@link #KEEP_EVERY_MS} of the agent's time so the robot's motion
 * shows too. The robot's path is kept whole but thinned to one point per {@link #PATH_EVERY_MS}
 * (a 10-minute run of 40 ms steps: 5 000 points). Thread-safe: the agent's thread records, the web server's
 * threads read.
 */
public final class MindHistory {
    /** Without a change of mind, a frame is still kept this often (agent's clock, ms). */
    static final long KEEP_EVERY_MS = 250;
    /** One point of the robot's path this often (ms). */
    static final long PATH_EVERY_MS = 100;

    /**
     * A mind and its robot (null for an agent without a body) at one instant; {@code index}
     * counts kept frames (negative: read back from the archive).
     */
    public record Frame(long index, MindState mind, RobotView robot) {
    }

    private final String agent;
    private final int capacity;
    private final ArrayDeque<Frame> frames = new ArrayDeque<>();
    private final ArrayDeque<MindState.Selection> selections = new ArrayDeque<>();
    private volatile MindArchive archive;
    private List<String> plans = List.of();
    private long next;
    private Frame latest;
    private long version;
    private float[] path = new float[3 * 1024]; // t (s), x, z
    private int pathSize;
    /** Failed goals seen: the plans selected for {@code -!goal} events (with error, error_msg, code), the last ones kept. */
    private final ArrayDeque<MindState.Selection> failures = new ArrayDeque<>();
    private long failureCount;

    public MindHistory(String agent, int capacity) {
        this.agent = agent;
        this.capacity = capacity;
    }

    public String agent() {
        return agent;
    }

    /** Reads what the rings no longer hold from {@code past} (the step log being written, or a recorded run). */
    public void archive(MindArchive past) {
        this.archive = past;
    }

    /** Records a state; it becomes the latest frame, and a kept one if the mind changed or time passed. */
    public synchronized void record(MindState mind, RobotView robot, List<String> planLibrary) {
        plans = planLibrary;
        for (MindState.Selection s : mind.selections()) {
            if (selections.size() >= capacity) {
                selections.removeFirst();
            }
            selections.addLast(s);
            noteFailure(s);
        }
        if (robot != null) {
            addToPath(mind.timeMs(), robot.x(), robot.z());
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

    /** Counts a selection for a failed goal ({@code -!goal} event), keeping the last ones. */
    public synchronized void noteFailure(MindState.Selection s) {
        if (!s.event().startsWith("-!")) {
            return;
        }
        failureCount++;
        if (failures.size() >= capacity) {
            failures.removeFirst();
        }
        failures.addLast(s);
    }

    /** {@return the failures counted and the last ones, for the failures panel} */
    public synchronized Map<String, Object> failures() {
        return Map.of("count", failureCount, "recent", new ArrayList<>(failures));
    }

    /** Adds a point to the robot's path, at most one per {@link #PATH_EVERY_MS}. */
    public synchronized void addToPath(long timeMs, double x, double z) {
        if (pathSize > 0 && timeMs - path[3 * (pathSize - 1)] * 1000 < PATH_EVERY_MS) {
            return;
        }
        if (3 * pathSize == path.length) {
            path = Arrays.copyOf(path, path.length * 2);
        }
        path[3 * pathSize] = timeMs / 1000f;
        path[3 * pathSize + 1] = (float) x;
        path[3 * pathSize + 2] = (float) z;
        pathSize++;
    }

    /** {@return the robot's path up to {@code timeMs}, as [x, z] pairs} */
    public synchronized List<float[]> pathUpTo(long timeMs) {
        var out = new ArrayList<float[]>();
        for (int i = 0; i < pathSize && path[3 * i] * 1000 <= timeMs + 0.5; i++) {
            out.add(new float[] {path[3 * i + 1], path[3 * i + 2]});
        }
        return out;
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

    /** {@return the latest frame: the one recorded last, or a recorded run's last; null before any} */
    public Frame latest() {
        synchronized (this) {
            if (latest != null) {
                return latest;
            }
        }
        MindArchive a = archive;
        return a == null || a.lastTimeMs() < 0 ? null : read(() -> a.at(a.lastTimeMs()));
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

    /** {@return the frame at the last instant at or before {@code timeMs}: from the ring, else from the archive} */
    public Frame at(long timeMs) {
        MindArchive a = archive;
        synchronized (this) {
            Frame first = frames.peekFirst();
            if (first != null && (first.mind().timeMs() <= timeMs || a == null || a.firstTimeMs() < 0)) {
                Frame best = first;
                for (Frame f : frames) {
                    if (f.mind().timeMs() <= timeMs) {
                        best = f;
                    }
                }
                return best;
            }
        }
        return a == null ? null : read(() -> a.at(timeMs));
    }

    /** {@return the times the slider spans: the archive's first (or the ring's), and the latest} */
    public long[] range() {
        MindArchive a = archive;
        long first, last;
        synchronized (this) {
            first = frames.isEmpty() ? -1 : frames.peekFirst().mind().timeMs();
            last = latest == null ? -1 : latest.mind().timeMs();
        }
        if (a != null && a.firstTimeMs() >= 0) {
            first = first < 0 ? a.firstTimeMs() : Math.min(first, a.firstTimeMs());
            last = Math.max(last, a.lastTimeMs());
        }
        return new long[] {first, last};
    }

    /** {@return the kept frames' indices and times} */
    public synchronized List<long[]> timeline() {
        var out = new ArrayList<long[]>(frames.size());
        frames.forEach(f -> out.add(new long[] {f.index(), f.mind().timeMs()}));
        return out;
    }

    public synchronized List<MindState.Selection> selections() {
        return new ArrayList<>(selections);
    }

    /** {@return up to {@code max} selections at or before {@code timeMs}: from the ring when it reaches back so far} */
    public List<MindState.Selection> selectionsUpTo(long timeMs, int max) {
        MindArchive a = archive;
        synchronized (this) {
            MindState.Selection first = selections.peekFirst();
            if (a == null || a.firstTimeMs() < 0 || (first != null && first.timeMs() <= timeMs)) {
                var out = new ArrayList<MindState.Selection>();
                for (MindState.Selection s : selections) {
                    if (s.timeMs() <= timeMs) {
                        out.add(s);
                    }
                }
                return out.size() > max ? new ArrayList<>(out.subList(out.size() - max, out.size())) : out;
            }
        }
        return read(() -> a.selectionsUpTo(timeMs, max));
    }

    /**
     * Hands every mind of the run so far to {@code each}, in time order: those on disk (every
     * step), then the kept frames after them (for the time views).
     */
    public void forEachMind(Consumer<MindState> each) {
        MindArchive a = archive;
        long after = -1;
        if (a != null && a.lastTimeMs() >= 0) {
            after = a.lastTimeMs();
            read(() -> {
                a.forEachMind(each);
                return null;
            });
        }
        List<Frame> recent;
        synchronized (this) {
            recent = new ArrayList<>(frames);
        }
        for (Frame f : recent) {
            if (f.mind().timeMs() > after) {
                each.accept(f.mind());
            }
        }
    }

    public synchronized List<String> plans() {
        return plans;
    }

    /** Sets the plan library (a recorded run's, or before the first frame). */
    public synchronized void plans(List<String> library) {
        plans = List.copyOf(library);
    }

    private interface Read<T> {
        T get() throws IOException;
    }

    private static <T> T read(Read<T> r) {
        try {
            return r.get();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
