package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Trigger;

/** Observes changes of the circumstance (used by {@code .wait}); all methods default to nothing. */
public interface CircumstanceListener {
    default void eventAdded(Event e) {
    }

    /**
     * {@return whether this listener needs to hear of the external belief event {@code op b} when no
     * plan is relevant for it} Such an event is not made at all unless some listener does: a
     * {@code .wait} for a time or for another event, or a probe of intentions, then costs every
     * percept change nothing. The default hears them all.
     */
    default boolean hearsBeliefEvent(Trigger.Op op, Literal b) {
        return true;
    }

    default void intentionAdded(Intention i) {
    }

    default void intentionDropped(Intention i) {
    }
}
