package jacabot.app.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.function.Consumer;

/** The logs a run hands out a line at a time (event log, link log), written to a file as they come. */
final class LineSink {
    private LineSink() {
    }

    /** {@return a sink writing each line and a newline to {@code w}; a write failure stops the run that writes} */
    static Consumer<String> into(Writer w) {
        return line -> {
            try {
                w.write(line);
                w.write('\n');
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        };
    }
}
