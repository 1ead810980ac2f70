package jacabot.sim.engine;

/** Observes a world. Every method has an empty default, so implement only what you need. */
public interface WorldListener {
    /** A scripted event or a supervisor action took effect at simulated time {@code timeMs}. */
    default void eventFired(long timeMs, String description) {
    }

    /** A scripted event could not be carried out (e.g. its object was already removed). */
    default void eventFailed(long timeMs, String description, String reason) {
    }

    /** A control step ended. */
    default void controlStepEnded(long timeMs) {
    }
}
