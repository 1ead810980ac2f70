package jacabot.agent.semantics;

/** Observes changes of the circumstance (used by {@code .wait}); all methods default to nothing. */
public interface CircumstanceListener {
    default void eventAdded(Event e) {
    }

    default void intentionAdded(Intention i) {
    }

    default void intentionDropped(Intention i) {
    }
}
