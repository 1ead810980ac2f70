package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** Records log lines as {@code info source: message} / {@code warning source: message}. */
final class RecordingLogger implements CartagoLogger {
    private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();

    @Override
    public void info(String source, String message) {
        lines.add("info " + source + ": " + message);
    }

    @Override
    public void warning(String source, String message, Throwable cause) {
        lines.add("warning " + source + ": " + message);
    }

    /** {@return the next line, waiting up to 10 s} */
    String next() {
        try {
            String line = lines.poll(10, TimeUnit.SECONDS);
            if (line == null) {
                fail("nothing logged within 10 s");
            }
            return line;
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }
}
