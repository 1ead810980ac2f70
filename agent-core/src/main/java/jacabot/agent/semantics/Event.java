package jacabot.agent.semantics;

import jacabot.agent.syntax.Trigger;

/**
 * An event: a trigger and, for internal events, the intention waiting for it (null for external
 * events, Jason's {@code EmptyInt}).
 */
public record Event(Trigger trigger, Intention intention) {
    public boolean isExternal() {
        return intention == null;
    }

    public boolean isAtomic() {
        return intention != null && intention.isAtomic();
    }

    @Override
    public String toString() {
        return trigger.toString();
    }
}
