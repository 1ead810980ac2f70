package jacabot.sim;

import java.util.function.Consumer;

/**
 * Runs a world in one of three modes: {@link Mode#STEP} (one control step per {@link #stepOnce()}
 * call), {@link Mode#FAST} (as fast as possible) and {@link Mode#REAL_TIME} (paced to the wall
 * clock times {@link #setSpeedFactor(double) a factor}). The wall clock only paces the loop and
 * measures the real-time factor; simulated time still advances only by {@code SimWorld.step()}.
 * Before each control step the runner calls the controller, if any, with the world.
 */
public final class SimRunner {
    /** How the loop advances. */
    public enum Mode { STEP, FAST, REAL_TIME }

    private final SimWorld world;
    private final Consumer<SimWorld> controller;
    private final Consumer<SimWorld> unlocked;
    private volatile Mode mode = Mode.REAL_TIME;
    private volatile double speedFactor = 1.0;
    private volatile boolean paused;
    private volatile boolean running;
    private volatile double measuredFactor = Double.NaN;
    private int singleSteps;
    private Thread thread;
    private long anchorWallNs, anchorSimMs, windowWallNs, windowSimMs;

    /** @param controller called before each control step, or null */
    public SimRunner(SimWorld world, Consumer<SimWorld> controller) {
        this(world, controller, null);
    }

    /**
     * @param controller called before each control step with the world's lock held, or null
     * @param unlocked   called after it without the lock, or null: a lockstep controller waits there for
     *                   a remote answer, so a viewer still reads the world meanwhile; what it changes in
     *                   the world it changes inside {@code synchronized (world)}
     */
    public SimRunner(SimWorld world, Consumer<SimWorld> controller, Consumer<SimWorld> unlocked) {
        this.world = world;
        this.controller = controller;
        this.unlocked = unlocked;
    }

    public SimWorld world() {
        return world;
    }

    public Mode mode() {
        return mode;
    }

    public void setMode(Mode mode) {
        this.mode = mode;
        reanchor();
    }

    public double speedFactor() {
        return speedFactor;
    }

    /** Sets the real-time factor aimed at in {@link Mode#REAL_TIME} (e.g. 2 = twice as fast as real time). */
    public void setSpeedFactor(double factor) {
        if (!(factor > 0)) {
            throw new IllegalArgumentException("speed factor must be > 0");
        }
        this.speedFactor = factor;
        reanchor();
    }

    /** {@return the measured simulated seconds per wall-clock second, NaN before a second has passed} */
    public double realTimeFactor() {
        return measuredFactor;
    }

    /** Runs the controller, then one control step. */
    public void stepOnce() {
        if (controller != null) {
            synchronized (world) {
                controller.accept(world);
            }
        }
        if (unlocked != null) {
            unlocked.accept(world);
        }
        world.step();
        measure();
    }

    /** Runs {@code seconds} of simulated time in the calling thread, in the current mode (STEP runs like FAST). */
    public void runFor(double seconds) {
        long end = world.timeMs() + Math.round(seconds * 1000);
        reanchor();
        while (world.timeMs() < end) {
            stepOnce();
            pace();
        }
    }

    /** Starts the loop in a background thread (for a viewer); paused or in STEP mode it waits for {@link #singleStep()}. */
    public synchronized void start() {
        if (running) {
            return;
        }
        running = true;
        reanchor();
        thread = new Thread(this::loop, "sim-runner");
        thread.setDaemon(true);
        thread.start();
    }

    /** Stops the background loop and waits for it. */
    public void stop() throws InterruptedException {
        Thread t;
        synchronized (this) {
            running = false;
            notifyAll();
            t = thread;
        }
        if (t != null) {
            t.join();
        }
    }

    public synchronized void setPaused(boolean paused) {
        this.paused = paused;
        reanchor();
        notifyAll();
    }

    public boolean isPaused() {
        return paused;
    }

    /** Asks the background loop for one control step while paused or in STEP mode. */
    public synchronized void singleStep() {
        singleSteps++;
        notifyAll();
    }

    private void loop() {
        while (running) {
            synchronized (this) {
                while (running && (paused || mode == Mode.STEP) && singleSteps == 0) {
                    try {
                        wait();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return;
                    }
                }
                if (!running) {
                    return;
                }
                if (singleSteps > 0) {
                    singleSteps--;
                }
            }
            stepOnce();
            pace();
        }
    }

    private synchronized void reanchor() {
        anchorWallNs = System.nanoTime();
        anchorSimMs = world.timeMs();
        windowWallNs = anchorWallNs;
        windowSimMs = anchorSimMs;
    }

    private void pace() {
        if (mode != Mode.REAL_TIME || paused) {
            return;
        }
        long simElapsedMs = world.timeMs() - anchorSimMs;
        long targetNs = anchorWallNs + (long) (simElapsedMs * 1e6 / speedFactor);
        long sleepNs = targetNs - System.nanoTime();
        if (sleepNs > 0) {
            try {
                Thread.sleep(sleepNs / 1_000_000, (int) (sleepNs % 1_000_000));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void measure() {
        long now = System.nanoTime();
        if (now - windowWallNs >= 1_000_000_000L) {
            measuredFactor = (world.timeMs() - windowSimMs) / 1000.0 / ((now - windowWallNs) / 1e9);
            windowWallNs = now;
            windowSimMs = world.timeMs();
        }
    }
}
