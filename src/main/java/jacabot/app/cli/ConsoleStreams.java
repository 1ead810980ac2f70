package jacabot.app.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.function.LongSupplier;

/** The commands print through picocli's writers; the run drivers want a PrintStream: this joins them. */
final class ConsoleStreams {
    private ConsoleStreams() {
    }

    /** {@return a PrintStream whose lines go to {@code writer} (UTF-8, flushed at each line)} */
    static PrintStream of(PrintWriter writer) {
        OutputStream bytes = new OutputStream() {
            private final ByteArrayOutputStream line = new ByteArrayOutputStream();

            @Override
            public synchronized void write(int b) {
                line.write(b);
                if (b == '\n') {
                    flush();
                }
            }

            @Override
            public synchronized void flush() {
                if (line.size() > 0) {
                    writer.write(line.toString(StandardCharsets.UTF_8));
                    line.reset();
                }
                writer.flush();
            }
        };
        return new PrintStream(bytes, true, StandardCharsets.UTF_8);
    }

    /**
     * {@return a PrintStream whose lines go to {@code file}, each after {@code t=S.SS }, the simulated
     * time in seconds that {@code millis} gives when the line is printed (a sweep's console kept per run)};
     * closing it flushes {@code file} and leaves it open
     */
    static PrintStream stamped(Writer file, LongSupplier millis) {
        return of(new PrintWriter(new Writer() {
            private boolean lineStart = true;

            @Override
            public void write(char[] chars, int off, int len) throws IOException {
                for (int i = off; i < off + len; i++) {
                    if (lineStart) {
                        file.write(String.format(Locale.ROOT, "t=%.2f ", millis.getAsLong() / 1000.0));
                        lineStart = false;
                    }
                    file.write(chars[i]);
                    lineStart = chars[i] == '\n';
                }
            }

            @Override
            public void flush() throws IOException {
                file.flush();
            }

            @Override
            public void close() throws IOException {
                flush();
            }
        }));
    }
}
