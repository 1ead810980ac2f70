package jacabot.cartago;

import java.io.PrintStream;

/**
 * Where the runtime and {@link Artifact#log(String)} write: pluggable, so that tests and the
 * launcher decide; the default goes to the JDK's platform logger.
 */
public interface CartagoLogger {
    /** Logs an informative message from {@code source} (an artifact or workspace name). */
    void info(String source, String message);

    /** Logs a problem from {@code source}; {@code cause} may be null. */
    void warning(String source, String message, Throwable cause);

    /** {@return a logger writing to {@code System.getLogger("jacabot.cartago")}} */
    static CartagoLogger platform() {
        System.Logger logger = System.getLogger("jacabot.cartago");
        return new CartagoLogger() {
            @Override
            public void info(String source, String message) {
                logger.log(System.Logger.Level.INFO, "[" + source + "] " + message);
            }

            @Override
            public void warning(String source, String message, Throwable cause) {
                logger.log(System.Logger.Level.WARNING, "[" + source + "] " + message, cause);
            }
        };
    }

    /**
     * {@return a logger writing console lines {@code [source] message}, as Jason's console shows
     * agents' lines (warnings with their cause's message, no stack trace)}
     */
    static CartagoLogger console(PrintStream out) {
        return new CartagoLogger() {
            @Override
            public void info(String source, String message) {
                out.println("[" + source + "] " + message);
            }

            @Override
            public void warning(String source, String message, Throwable cause) {
                out.println("[" + source + "] " + message + (cause == null ? "" : ": " + cause));
            }
        };
    }

    /** {@return a logger that drops everything} */
    static CartagoLogger silent() {
        return new CartagoLogger() {
            @Override
            public void info(String source, String message) {
            }

            @Override
            public void warning(String source, String message, Throwable cause) {
            }
        };
    }
}
