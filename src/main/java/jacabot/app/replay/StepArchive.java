package jacabot.app.replay;

import jacabot.app.inspector.Inspector;
import jacabot.app.inspector.MindArchive;
import jacabot.app.inspector.MindHistory;
import jacabot.app.inspector.MindState;
import jacabot.app.inspector.RobotView;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.zip.DataFormatException;
import java.util.zip.GZIPInputStream;
import java.util.zip.Inflater;

/**
 * A step log read on demand: an index of its gzip members (where each starts, its first step's
 * time), and any instant rebuilt from the key step that starts its member. Live, the writer
 * announces each member as it reaches the disk ({@link #live}); for a recorded run, one pass over
 * the file finds them ({@link #open}). Only the index (a few entries a minute) stays in memory.
 */
public final class StepArchive implements MindArchive {
    private final Path file;
    private final StepLog.Header header;
    private final List<StepLog.Chunk> chunks = new ArrayList<>();

    private StepArchive(Path file, StepLog.Header header) {
        this.file = file;
        this.header = header;
    }

    /** {@return an archive of the step log being written to {@code file}; hand it the writer's chunks ({@link #add})} */
    public static StepArchive live(Path file, StepLog.Header header) {
        return new StepArchive(file, header);
    }

    /**
     * Indexes a recorded step log in one pass, handing every step's pose to {@code path}
     * (time ms, x, z) on the way.
     */
    public static StepArchive open(Path dirOrFile, PathSink path) throws IOException {
        Path file = Files.isDirectory(dirOrFile) ? dirOrFile.resolve(StepLog.FILE) : dirOrFile;
        if (!Files.isRegularFile(file)) {
            throw new IOException(file + ": no step log (written by every `jacabot experiment` run)");
        }
        StepLog.Header header;
        try (var in = new StepLog.Reader(file)) {
            header = in.header();
        }
        var archive = new StepArchive(file, header);
        byte[] all = Files.readAllBytes(file);
        int pos = 0;
        long step = 0;
        while (pos < all.length) {
            boolean plain = all.length - pos > 10 && (all[pos] & 0xff) == 0x1f && (all[pos + 1] & 0xff) == 0x8b
                    && all[pos + 3] == 0;
            if (!plain) {
                throw new IOException(file + ": not a step log of gzip members at byte " + pos);
            }
            var inflater = new Inflater(true);
            inflater.setInput(all, pos + 10, all.length - pos - 10);
            var text = new ByteArrayOutputStream();
            byte[] buf = new byte[1 << 16];
            try {
                while (!inflater.finished()) {
                    int n = inflater.inflate(buf);
                    if (n == 0 && (inflater.needsInput() || inflater.needsDictionary())) {
                        throw new IOException(file + ": truncated at byte " + pos);
                    }
                    text.write(buf, 0, n);
                }
            } catch (DataFormatException e) {
                throw new IOException(file + ": corrupt gzip member at byte " + pos + ": " + e.getMessage());
            }
            int end = all.length - inflater.getRemaining() + 8; // the member's CRC and size follow its data
            inflater.end();
            long first = -1, last = -1, firstStep = step;
            for (String line : text.toString(StandardCharsets.UTF_8).split("\n")) {
                if (line.isEmpty() || line.startsWith("{\"format\"")) {
                    continue;
                }
                // only the time and the position, without parsing the whole line (a 10-minute log: 15 000 lines)
                long t = (long) number(line, "{\"t\":", 0);
                int body = line.indexOf("\"body\":{");
                first = first < 0 ? t : first;
                last = t;
                path.point(t, number(line, "\"x\":", body), number(line, "\"z\":", body));
                if (line.contains("\"event\":\"-!")) { // a failed goal: read the line whole for its selections
                    var mind = StepLog.parse(line).mind();
                    mind.selections().forEach(path::failure);
                }
                step++;
            }
            if (first >= 0) {
                archive.add(new StepLog.Chunk(pos, firstStep, first, last));
            }
            pos = end;
        }
        return archive;
    }

    /**
     * Shows a recorded run in {@code inspector}, as its page shows a live one: the robot agent's
     * whole history read on demand, its world and its plots. {@return the archive}
     */
    public static StepArchive show(Inspector inspector, Path dirOrFile) throws IOException {
        StepArchive archive = history(inspector, dirOrFile, "robot");
        inspector.world(archive.header().start());
        inspector.showPlots(Files.isDirectory(dirOrFile) ? dirOrFile : dirOrFile.toAbsolutePath().getParent());
        return archive;
    }

    /**
     * Adds a recorded run's agent to {@code inspector} as {@code name} (e.g. a what-if beside its
     * run): its history read on demand, its path and failures. {@return the archive}
     */
    public static StepArchive history(Inspector inspector, Path dirOrFile, String name) throws IOException {
        MindHistory h = inspector.add(name);
        StepArchive archive = open(dirOrFile, new PathSink() {
            @Override
            public void point(long timeMs, double x, double z) {
                h.addToPath(timeMs, x, z);
            }

            @Override
            public void failure(MindState.Selection s) {
                h.noteFailure(s);
            }
        });
        h.archive(archive);
        if (archive.header().plans() != null) {
            h.plans(archive.header().plans());
        }
        return archive;
    }

    /** {@return the number after {@code key} (the first at or after {@code from}) in a step line} */
    private static double number(String line, String key, int from) throws IOException {
        int at = from < 0 ? -1 : line.indexOf(key, from);
        if (at < 0) {
            throw new IOException("not a step of a jacabot step log: " + (line.length() > 80 ? line.substring(0, 80) + "..." : line));
        }
        int start = at + key.length(), end = start;
        while (end < line.length() && "-+.0123456789eE".indexOf(line.charAt(end)) >= 0) {
            end++;
        }
        return Double.parseDouble(line.substring(start, end));
    }

    /** Receives a run's path, point by point, and its failed goals. */
    public interface PathSink {
        void point(long timeMs, double x, double z);

        /** A plan selected for a {@code -!goal} event (and others of its step, which it may ignore). */
        default void failure(MindState.Selection s) {
        }
    }

    /** Adds a member of steps now on disk (the writer's {@link StepLog.Writer#onChunk}). */
    public synchronized void add(StepLog.Chunk c) {
        chunks.add(c);
    }

    public StepLog.Header header() {
        return header;
    }

    @Override
    public synchronized long firstTimeMs() {
        return chunks.isEmpty() ? -1 : chunks.get(0).firstTimeMs();
    }

    @Override
    public synchronized long lastTimeMs() {
        return chunks.isEmpty() ? -1 : chunks.get(chunks.size() - 1).lastTimeMs();
    }

    /** {@return the member holding {@code timeMs} (the first when before it), its index, or -1 when empty} */
    private synchronized int chunkAt(long timeMs) {
        int best = chunks.isEmpty() ? -1 : 0;
        for (int i = 0; i < chunks.size() && chunks.get(i).firstTimeMs() <= timeMs; i++) {
            best = i;
        }
        return best;
    }

    private synchronized StepLog.Chunk chunk(int i) {
        return chunks.get(i);
    }

    /** Reads the steps of member {@code i} (and on, while {@code each} asks for more). */
    private void read(int i, Visitor each) throws IOException {
        StepLog.Chunk c = chunk(i);
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            ch.position(c.offset());
            var in = new BufferedReader(new InputStreamReader(new GZIPInputStream(Channels.newInputStream(ch), 1 << 14),
                    StandardCharsets.UTF_8));
            String line;
            long step = c.firstStep();
            var images = new ImageText.Resolver(); // a member starts with a key step: its image is whole
            while ((line = in.readLine()) != null) {
                if (line.startsWith("{\"format\"")) {
                    continue; // a log of one member starts with its header
                }
                StepLog.Step s = StepLog.parse(line);
                try {
                    s = s.withReadings(images.resolve(s.readings()));
                } catch (IllegalArgumentException e) {
                    throw new IOException(file + ": step " + step + ": " + e.getMessage());
                }
                if (!each.step(step++, s)) {
                    return;
                }
            }
        }
    }

    private interface Visitor {
        boolean step(long number, StepLog.Step s) throws IOException;
    }

    @Override
    public MindHistory.Frame at(long timeMs) throws IOException {
        int i = chunkAt(timeMs);
        if (i < 0) {
            return null;
        }
        long end = Math.min(timeMs, lastTimeMs()); // a member being written is never read
        var state = StepState.from(header);
        var found = new MindHistory.Frame[1];
        read(i, (n, s) -> {
            if (found[0] != null && s.timeMs() > end) {
                return false;
            }
            MindState mind = state.apply(s);
            found[0] = new MindHistory.Frame(n, mind, view(s, state.objects()));
            return s.timeMs() < end;
        });
        return found[0];
    }

    /** The selections of the member holding {@code timeMs} up to it, and of the member before. */
    @Override
    public List<MindState.Selection> selectionsUpTo(long timeMs, int max) throws IOException {
        int i = chunkAt(timeMs);
        if (i < 0) {
            return List.of();
        }
        long end = Math.min(timeMs, lastTimeMs());
        var out = new ArrayList<MindState.Selection>();
        read(Math.max(0, i - 1), (n, s) -> {
            if (s.timeMs() > end) {
                return false;
            }
            if (s.mind() != null && s.mind().selections() != null) {
                out.addAll(s.mind().selections());
            }
            return s.timeMs() < end;
        });
        return out.size() > max ? new ArrayList<>(out.subList(out.size() - max, out.size())) : out;
    }

    @Override
    public void forEachMind(Consumer<MindState> each) throws IOException {
        if (chunkAt(0) < 0) {
            return;
        }
        long end = lastTimeMs(); // a member being written is never read
        var state = StepState.from(header);
        read(0, (n, s) -> {
            if (s.timeMs() > end) {
                return false;
            }
            each.accept(state.apply(s));
            return s.timeMs() < end;
        });
    }

    static RobotView view(StepLog.Step s, Map<String, StepLog.Moved> objects) {
        var placed = new ArrayList<RobotView.Placed>(objects.size());
        objects.forEach((id, m) -> placed.add(new RobotView.Placed(id, m.x(), m.z(), m.heading(), m.carriedBy())));
        var b = s.body();
        return new RobotView(s.timeMs(), b.x(), b.z(), b.heading(), b.battery(), b.left(), b.right(), s.commands(), placed, s.readings());
    }
}
