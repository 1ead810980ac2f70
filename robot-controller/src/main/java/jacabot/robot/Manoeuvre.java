package jacabot.robot;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.function.BooleanSupplier;

/**
 * A command the functional layer carries out over several control steps ({@code backward},
 * {@code turnAround}, {@code catching}, {@code putDown}): a queue of phases, each an action started
 * once and a condition that ends it, with a time cap so that a jammed gripper cannot hold the robot
 * forever. Advanced by {@link #tick(long)} once per control step, in simulated time.
 */
final class Manoeuvre {
    /** One phase: what to do when it starts, and when it is over. */
    record Phase(Runnable start, BooleanSupplier done, long capMs) {
    }

    private final String name;
    private final Deque<Phase> phases = new ArrayDeque<>();
    private Phase current;
    private long currentStartMs;

    Manoeuvre(String name) {
        this.name = name;
    }

    String name() {
        return name;
    }

    /** Adds a phase that lasts until {@code done} holds (or {@code capMs} of simulated time pass). */
    Manoeuvre then(Runnable start, BooleanSupplier done, long capMs) {
        phases.add(new Phase(start, done, capMs));
        return this;
    }

    /** Adds a phase that lasts {@code ms} of simulated time. */
    Manoeuvre thenFor(Runnable start, long ms) {
        phases.add(new Phase(start, () -> false, ms));
        return this;
    }

    /** Advances the manoeuvre at simulated time {@code nowMs}; {@return whether it is finished} */
    boolean tick(long nowMs) {
        while (true) {
            if (current != null) {
                if (!current.done().getAsBoolean() && nowMs - currentStartMs < current.capMs()) {
                    return false;
                }
                current = null;
            }
            if (phases.isEmpty()) {
                return true;
            }
            current = phases.poll();
            currentStartMs = nowMs;
            current.start().run();
        }
    }
}
