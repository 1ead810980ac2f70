package jacabot.app.inspector;

import jacabot.app.console.ConsoleLog;
import java.io.BufferedWriter;
import java.io.Closeable;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * Writes a run's console to its folder as it is made ({@value ConsoleFile#FILE}): every line the
 * agents and artifacts print, with the simulated time it was printed at, and the event log's lines
 * (the world's and the recorder's, already timed) as they come, so that the inspector's console
 * panel can read any stretch of it by time, live or after the run, without the run holding it in
 * memory. Lines are {@code t=SECONDS text}, as in {@code event-log.txt}; written to disk at each
 * control step ({@link #events}) and at {@link #close}.
 */
public final class ConsoleRecorder implements Closeable {
    private final Path file;
    private final BufferedWriter out;
    private final LongSupplier clockMs;
    private int eventsWritten;
    private IOException failure;

    private ConsoleRecorder(Path file, LongSupplier clockMs) throws IOException {
        this.file = file;
        this.out = Files.newBufferedWriter(file, StandardCharsets.UTF_8);
        this.clockMs = clockMs;
    }

    /**
     * Opens {@value ConsoleFile#FILE} in {@code runDir} (replacing one there).
     *
     * @param clockMs the run's simulated time, read when an agent prints
     */
    public static ConsoleRecorder open(Path runDir, LongSupplier clockMs) throws IOException {
        return new ConsoleRecorder(runDir.resolve(ConsoleFile.FILE), clockMs);
    }

    /** {@return a console stream that prints to {@code console} and writes each line here too, with its time} */
    public PrintStream tee(PrintStream console) {
        return ConsoleLog.lines(line -> {
            console.println(line);
            line(clockMs.getAsLong(), line);
        });
    }

    /** Writes one line at {@code timeMs}. */
    public synchronized void line(long timeMs, String text) {
        write(String.format(Locale.ROOT, "t=%.3f ", timeMs / 1000.0) + text);
    }

    /**
     * Writes the event log's lines not written yet (it only grows) and puts everything so far on
     * disk: called once per control step, on the step's thread.
     */
    public synchronized void events(List<String> eventLog) {
        for (; eventsWritten < eventLog.size(); eventsWritten++) {
            write(eventLog.get(eventsWritten));
        }
        try {
            out.flush();
        } catch (IOException e) {
            failure = e;
        }
    }

    private void write(String line) {
        if (failure != null) {
            return; // a full disk loses the console file, not the run
        }
        try {
            out.write(line);
            out.write('\n');
        } catch (IOException e) {
            failure = e;
        }
    }

    /**
     * Puts the rest on disk.
     *
     * @throws UncheckedIOException when a write failed, now or during the run
     */
    @Override
    public synchronized void close() {
        try {
            out.close();
        } catch (IOException e) {
            failure = failure == null ? e : failure;
        }
        if (failure != null) {
            throw new UncheckedIOException("cannot write the console file: " + failure.getMessage(), failure);
        }
    }

    /** Puts the rest on disk; a write that failed, now or during the run, is told to {@code warn} with the file's path. */
    public void close(Consumer<String> warn) {
        try {
            close();
        } catch (UncheckedIOException e) {
            warn.accept(file + ": " + e.getMessage());
        }
    }
}
