package jacabot.app.cli;

/**
 * A JVM shutdown hook for the span of one run: on Ctrl-C or SIGTERM the JVM runs {@code onExit}
 * (closing the run, or signalling it and waiting for it to write its files); when the run ends
 * first, {@link #remove} takes the hook away again.
 */
final class ExitHook {
    private final Thread thread;

    private ExitHook(Thread thread) {
        this.thread = thread;
    }

    /** {@return the hook, installed: {@code onExit} runs on a thread named {@code name} if the JVM shuts down} */
    static ExitHook install(String name, Runnable onExit) {
        Thread t = new Thread(onExit, name);
        Runtime.getRuntime().addShutdownHook(t);
        return new ExitHook(t);
    }

    /** Removes the hook; while the JVM is shutting down it is already running, and stays. */
    void remove() {
        try {
            Runtime.getRuntime().removeShutdownHook(thread);
        } catch (IllegalStateException shuttingDown) {
            // the hook is running: a hook that waits for the run sees it end
        }
    }
}
