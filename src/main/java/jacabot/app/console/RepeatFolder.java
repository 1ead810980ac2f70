package jacabot.app.console;

import java.util.ArrayDeque;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Folds the agents' repeated console lines. A line already seen among the last {@link #WINDOW}
 * lines is not printed but counted; once it has not come back for {@link #WINDOW} lines (or at
 * {@link #flush()}), one line says how often it came: {@code [robot] high left (x12 more)}; a
 * plain run of one line is counted as soon as another line ends it.
 * A window rather than "the previous line" because avoidance loops repeat in cycles
 * ("Obstacle: 353", "Wait avoiding", "high left", ...). The first occurrence is always printed at
 * once, so the story is never delayed; only its repetitions are.
 */
public final class RepeatFolder {
    /** How many recent lines a repetition is looked for in. */
    public static final int WINDOW = 8;

    private final Consumer<String> sink;
    private final ArrayDeque<String> recent = new ArrayDeque<>();
    private final Map<String, Integer> folded = new LinkedHashMap<>();
    private String last;
    private int streak;

    /** @param sink where the lines to print go */
    public RepeatFolder(Consumer<String> sink) {
        this.sink = sink;
    }

    /** Takes one console line (without its line break). */
    public synchronized void line(String line) {
        if (line.equals(last)) {
            streak++;
        } else {
            // a plain run of one line ends: its count comes now, before the line that ended it
            if (streak > 1 && folded.getOrDefault(last, 0) == streak - 1) {
                report(last);
                recent.removeIf(last::equals);
            }
            last = line;
            streak = 1;
        }
        boolean repeat = recent.contains(line);
        recent.addLast(line);
        if (recent.size() > WINDOW) {
            String gone = recent.removeFirst();
            if (!recent.contains(gone)) {
                report(gone);
            }
        }
        if (repeat) {
            folded.merge(line, 1, Integer::sum);
        } else {
            sink.accept(line);
        }
    }

    /** Prints the counts of the lines folded so far and starts afresh (before other output, at the end). */
    public synchronized void flush() {
        for (var e : folded.entrySet()) {
            sink.accept(counted(e.getKey(), e.getValue()));
        }
        folded.clear();
        recent.clear();
        last = null;
        streak = 0;
    }

    private void report(String line) {
        Integer n = folded.remove(line);
        if (n != null) {
            sink.accept(counted(line, n));
        }
    }

    private static String counted(String line, int more) {
        return line + " (x" + more + " more)";
    }
}
