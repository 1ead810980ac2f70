package jacabot.app.run;

import jacabot.sim.SimWorld;
import jacabot.sim.engine.WorldListener;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.function.Supplier;

/**
 * What a recording needs of the world at each control step, read on the simulation thread when
 * the step's readings are about to be sampled, and taken on the agent side's thread when it
 * handles that step. In lockstep the world waits for the agent, so this is what the agent's
 * thread would read itself; in a pipelined lockstep the world is a step ahead by then, and only
 * this keeps a recording a function of world, agent and seed.
 *
 * @param <T> what is read
 */
public final class WorldAtStep<T> implements WorldListener {
    private final SimWorld world;
    private final Supplier<T> read;
    private final ConcurrentSkipListMap<Long, T> byTime = new ConcurrentSkipListMap<>();

    private WorldAtStep(SimWorld world, Supplier<T> read) {
        this.world = world;
        this.read = read;
    }

    /**
     * Reads {@code read} now (the first step's world) and at the end of every control step, on the
     * simulation thread; call before the run, after the listeners whose state {@code read} reads.
     */
    public static <T> WorldAtStep<T> attach(SimWorld world, Supplier<T> read) {
        var w = new WorldAtStep<>(world, read);
        w.byTime.put(world.timeMs(), read.get());
        world.addListener(w);
        return w;
    }

    @Override
    public void controlStepEnded(long timeMs) {
        byTime.put(timeMs, read.get());
    }

    /**
     * {@return what was read at simulated time {@code simTimeMs}}, forgetting it and anything
     * earlier (steps no agent handled)
     *
     * @throws IllegalStateException when the world has not reached that time
     */
    public T take(long simTimeMs) {
        T t = byTime.get(simTimeMs);
        if (t == null) {
            throw new IllegalStateException("the world was not read at t=" + simTimeMs + " ms (it is at " + world.timeMs() + " ms)");
        }
        byTime.headMap(simTimeMs, true).clear();
        return t;
    }

    /** Stops reading the world. */
    public void detach() {
        world.removeListener(this);
    }
}
