package jacabot.app.inspector;

import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A run's console on disk, read on demand by simulated time for the inspector's console panel:
 * {@value #FILE} (the agents' lines and the event log's, {@code t=SECONDS text} each, in time
 * order; see {@link ConsoleRecorder}) or, for a run recorded without one, {@code event-log.txt}
 * (the world's and the recorder's lines only). The file may still be growing (a live run): each
 * query first reads what was appended since the last one, complete lines only. In memory: one
 * index entry (time, byte offset) per {@value #BLOCK} lines, never the lines themselves.
 */
public final class ConsoleFile {
    /** The console file in a run's folder. */
    public static final String FILE = "console.txt";
    /** The event log, read when a run has no console file. */
    public static final String EVENT_LOG = "event-log.txt";
    /** Lines per index entry. */
    static final int BLOCK = 128;
    /** At most this many lines in one answer. */
    public static final int MAX_LINES = 1000;

    /** A console line at its simulated time. */
    public record Line(long timeMs, String text) {
    }

    /**
     * Lines around an instant.
     *
     * @param lines   in file order
     * @param earlier whether lines before the first one exist
     * @param later   whether lines after the last one exist
     */
    public record Window(List<Line> lines, boolean earlier, boolean later) {
    }

    private final Path file;
    private long[] blockTimes = new long[64];
    private long[] blockOffsets = new long[64];
    private int blocks;
    private long indexedTo;
    private long lines;
    private long lastTime;
    /** The time of the line read last by {@link #read}: a line without one takes it. */
    private long timeOfLast;

    private ConsoleFile(Path file) {
        this.file = file;
    }

    /** {@return the console of the run in {@code runDir}: its {@value #FILE}, or its event log when it has none} */
    public static ConsoleFile of(Path runDir) {
        Path console = runDir.resolve(FILE);
        return new ConsoleFile(Files.exists(console) || !Files.exists(runDir.resolve(EVENT_LOG)) ? console : runDir.resolve(EVENT_LOG));
    }

    /** {@return the file read} */
    public Path file() {
        return file;
    }

    /** {@return up to {@code max} lines from {@code fromMs} to {@code toMs} (both included), in file order} */
    public List<Line> between(long fromMs, long toMs, int max) throws IOException {
        return between(fromMs, toMs, max, "");
    }

    /** {@return up to {@code max} lines from {@code fromMs} to {@code toMs} (both included) that contain {@code text}, in file order} */
    public synchronized List<Line> between(long fromMs, long toMs, int max, String text) throws IOException {
        catchUp();
        var out = new ArrayList<Line>();
        if (blocks == 0 || max <= 0) {
            return out;
        }
        try (var in = openBlock(blockBefore(fromMs))) {
            for (Line l = read(in); l != null; l = read(in)) {
                if (l.timeMs() > toMs || out.size() >= max) {
                    break;
                }
                if (l.timeMs() >= fromMs && l.text().contains(text)) {
                    out.add(l);
                }
            }
        }
        return out;
    }

    /** {@return up to {@code before} lines at or before {@code timeMs} and up to {@code after} lines after it} */
    public synchronized Window around(long timeMs, int before, int after) throws IOException {
        catchUp();
        if (blocks == 0) {
            return new Window(List.of(), false, false);
        }
        int first = Math.max(0, blockBefore(timeMs + 1) - (before + BLOCK - 1) / BLOCK);
        var upTo = new ArrayDeque<Line>();
        var out = new ArrayList<Line>();
        boolean earlier = first > 0, later = false;
        try (var in = openBlock(first)) {
            for (Line l = read(in); l != null; l = read(in)) {
                if (l.timeMs() <= timeMs) {
                    upTo.addLast(l);
                    if (upTo.size() > before) {
                        upTo.removeFirst();
                        earlier = true;
                    }
                } else if (out.size() < after) {
                    out.add(l);
                } else {
                    later = true;
                    break;
                }
            }
        }
        var all = new ArrayList<>(upTo);
        all.addAll(out);
        return new Window(all, earlier, later);
    }

    /**
     * {@return the inspector's answer to a query}: {@code t=MS} (with {@code before=N},
     * {@code after=N}, 40 each by default) the lines around that instant, with whether there are
     * earlier and later ones; {@code from=MS&to=MS} (with {@code max=N}, and {@code text=T}: only
     * the lines containing T) the lines of that stretch
     *
     * @throws IllegalArgumentException for a query that is neither
     */
    public Map<String, Object> answer(Map<String, String> query) throws IOException {
        long t = number(query.get("t"), -1), from = number(query.get("from"), -1), to = number(query.get("to"), Long.MAX_VALUE);
        long before = number(query.get("before"), 40), after = number(query.get("after"), 40), max = number(query.get("max"), MAX_LINES);
        if ((t < 0 && from < 0) || to < 0 || before < 0 || after < 0 || max < 0) {
            throw new IllegalArgumentException("console: give t=MS (with before=N, after=N) or from=MS and to=MS (with max=N): "
                    + "whole numbers, times in ms of simulated time");
        }
        var out = new LinkedHashMap<String, Object>();
        out.put("available", true);
        out.put("file", file.getFileName().toString());
        if (t >= 0) {
            Window w = around(t, (int) Math.min(before, MAX_LINES), (int) Math.min(after, MAX_LINES));
            out.put("lines", w.lines());
            out.put("earlier", w.earlier());
            out.put("later", w.later());
        } else {
            out.put("lines", between(from, to, (int) Math.min(max, MAX_LINES), query.getOrDefault("text", "")));
        }
        return out;
    }

    /** {@return a whole number given in a query, {@code otherwise} when missing, -1 when not one} */
    private static long number(String text, long otherwise) {
        try {
            return text == null ? otherwise : Long.parseLong(text);
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /** {@return the index of the last block whose first line is before {@code timeMs}, or 0} */
    private int blockBefore(long timeMs) {
        int i = Arrays.binarySearch(blockTimes, 0, blocks, timeMs);
        if (i < 0) {
            i = -i - 1;
        } else {
            while (i > 0 && blockTimes[i - 1] == timeMs) {
                i--;
            }
        }
        return Math.max(0, i - 1);
    }

    /** Indexes the complete lines appended since the last query. */
    private void catchUp() throws IOException {
        if (!Files.exists(file) || Files.size(file) <= indexedTo) {
            return;
        }
        try (var in = open(indexedTo)) {
            long at = indexedTo;
            var bytes = new ByteArrayOutputStream();
            for (int b = in.read(); b >= 0; b = in.read()) {
                if (b != '\n') {
                    bytes.write(b);
                    continue;
                }
                Line l = parse(bytes.toString(StandardCharsets.UTF_8), lastTime);
                if (lines % BLOCK == 0) {
                    if (blocks == blockTimes.length) {
                        blockTimes = Arrays.copyOf(blockTimes, blocks * 2);
                        blockOffsets = Arrays.copyOf(blockOffsets, blocks * 2);
                    }
                    blockTimes[blocks] = l.timeMs();
                    blockOffsets[blocks++] = at;
                }
                lines++;
                lastTime = l.timeMs();
                at += bytes.size() + 1;
                indexedTo = at;
                bytes.reset();
            }
        }
    }

    private InputStream openBlock(int block) throws IOException {
        timeOfLast = blockTimes[block];
        return open(blockOffsets[block]);
    }

    private InputStream open(long offset) throws IOException {
        FileChannel ch = FileChannel.open(file, StandardOpenOption.READ);
        ch.position(offset);
        return new BufferedInputStream(Channels.newInputStream(ch), 1 << 16);
    }

    /** {@return the next complete line (indexed ones only: a line being written is not read), or null} */
    private Line read(InputStream in) throws IOException {
        var bytes = new ByteArrayOutputStream();
        for (int b = in.read(); b >= 0; b = in.read()) {
            if (b == '\n') {
                Line l = parse(bytes.toString(StandardCharsets.UTF_8), timeOfLast);
                timeOfLast = l.timeMs();
                return l;
            }
            bytes.write(b);
        }
        return null;
    }

    /** {@return a {@code t=SECONDS text} line; a line without a time (a message's second line) takes {@code previous}} */
    static Line parse(String line, long previous) {
        if (line.startsWith("t=")) {
            int space = line.indexOf(' ');
            try {
                double s = Double.parseDouble(space < 0 ? line.substring(2) : line.substring(2, space));
                return new Line(Math.round(s * 1000), space < 0 ? "" : line.substring(space + 1));
            } catch (NumberFormatException e) {
                // not a time: the whole line is text
            }
        }
        return new Line(previous, line);
    }
}
