package jacabot.app.cli;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;

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
}
