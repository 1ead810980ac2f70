package jacabot.experiments.link;

/**
 * A daemon thread of one link that wakes, does its round and sleeps again until the link closes
 * ({@link Heartbeat}, {@link ConnectionWatchdog}).
 */
abstract class LinkThread {
    private final Thread thread;
    private volatile boolean stopped;

    LinkThread(String name) {
        thread = new Thread(this::run, name);
        thread.setDaemon(true);
    }

    /** {@return how long to sleep before the next round} */
    abstract long pauseMs();

    /** One round. */
    abstract void round();

    final void start() {
        thread.start();
    }

    final void stop() {
        stopped = true;
        thread.interrupt();
    }

    private void run() {
        try {
            while (!stopped) {
                Thread.sleep(pauseMs());
                round();
            }
        } catch (InterruptedException e) {
            // closing
        }
    }
}
