package jacabot.app.console;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;

/**
 * The one way the launcher's commands print, at one {@link Verbosity}: results always, jacabot's
 * own lines and the progress line by default, the agents' console folded by default
 * ({@link RepeatFolder}) and verbatim with {@code --verbose}, details only with {@code --verbose},
 * warnings always (on stderr). One lock for all of it, so lines from the agents' threads and the
 * command's own never cut into each other.
 */
public final class ConsoleLog {
    private final PrintWriter out;
    private final PrintWriter err;
    private final Verbosity level;
    private final RepeatFolder folder;
    private final PrintStream agents;
    private boolean inPlace;

    public ConsoleLog(PrintWriter out, PrintWriter err, Verbosity level) {
        this.out = out;
        this.err = err;
        this.level = level;
        this.folder = new RepeatFolder(this::println);
        this.agents = lines(this::agentLine);
    }

    /** {@return a log printing everything to {@code out} at {@code level} (tests, benches)} */
    public static ConsoleLog to(PrintStream out, Verbosity level) {
        var w = new PrintWriter(out, true, StandardCharsets.UTF_8);
        return new ConsoleLog(w, w, level);
    }

    public Verbosity level() {
        return level;
    }

    /** A result (a summary, the files written): printed at every level. */
    public void result(String line) {
        synchronized (this) {
            folder.flush();
            println(line);
        }
    }

    /** One of jacabot's own lines (what runs, the progress line): not with {@code --quiet}. */
    public void info(String line) {
        if (level != Verbosity.QUIET) {
            synchronized (this) {
                folder.flush();
                println(line);
            }
        }
    }

    /** A detail (link, controller, timings): only with {@code --verbose}. */
    public void detail(String line) {
        if (level == Verbosity.VERBOSE) {
            synchronized (this) {
                folder.flush();
                println(line);
            }
        }
    }

    /** A warning, on stderr at every level: {@code warning: message}. */
    public void warn(String message) {
        synchronized (this) {
            folder.flush();
            endInPlace();
            err.println("warning: " + message);
            err.flush();
        }
    }

    /**
     * A line redrawn in place on stderr (a progress bar), not with {@code --quiet}; the next other
     * line or {@link #endInPlace()} ends it.
     */
    public synchronized void inPlace(String text) {
        if (level != Verbosity.QUIET) {
            err.print("\r" + text);
            err.flush();
            inPlace = true;
        }
    }

    /** Ends the line being redrawn in place, if any. */
    public synchronized void endInPlace() {
        if (inPlace) {
            err.println();
            err.flush();
            inPlace = false;
        }
    }

    /**
     * {@return the stream for the agents' and artifacts' console ({@code [robot] text} lines)}:
     * dropped with {@code --quiet}, repeated lines folded by default, verbatim with {@code --verbose}
     */
    public PrintStream agents() {
        return agents;
    }

    /**
     * {@return the agents' console line for line, as Jason prints it (dropped with {@code --quiet})}:
     * for {@code jacabot run}, whose output users and the conformance checks compare with Jason's
     */
    public PrintStream agentsVerbatim() {
        return lines(line -> {
            if (level != Verbosity.QUIET) {
                synchronized (this) {
                    println(line);
                }
            }
        });
    }

    /** {@return a stream whose lines are {@link #info} lines (e.g. for the inspector's address)} */
    public PrintStream infoStream() {
        return lines(this::info);
    }

    /** Prints the counts of folded lines and flushes (at the end of a run). */
    public synchronized void flush() {
        folder.flush();
        out.flush();
        err.flush();
    }

    private void agentLine(String line) {
        switch (level) {
            case QUIET:
                return;
            case VERBOSE:
                synchronized (this) {
                    println(line);
                }
                return;
            default:
                synchronized (this) {
                    folder.line(line);
                }
        }
    }

    /** Called with the lock held (directly, or by the folder). */
    private void println(String line) {
        if (inPlace) {
            endInPlace();
        }
        out.println(line);
        out.flush();
    }

    /** {@return a PrintStream handing each complete line (UTF-8, no line break) to {@code sink}} */
    public static PrintStream lines(Consumer<String> sink) {
        OutputStream bytes = new OutputStream() {
            private final ByteArrayOutputStream line = new ByteArrayOutputStream();

            @Override
            public synchronized void write(int b) {
                if (b == '\n') {
                    endLine();
                } else {
                    line.write(b);
                }
            }

            /** A PrintStream writes a line's bytes at once: taken whole, not byte by byte. */
            @Override
            public synchronized void write(byte[] b, int off, int len) {
                int start = off;
                for (int i = off, end = off + len; i < end; i++) {
                    if (b[i] == '\n') {
                        line.write(b, start, i - start);
                        endLine();
                        start = i + 1;
                    }
                }
                line.write(b, start, off + len - start);
            }

            private void endLine() {
                String text = line.toString(StandardCharsets.UTF_8);
                line.reset();
                sink.accept(text.endsWith("\r") ? text.substring(0, text.length() - 1) : text);
            }

            @Override
            public synchronized void flush() {
                // a partial line waits for its end: a line is the unit that is folded
            }
        };
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }
}
