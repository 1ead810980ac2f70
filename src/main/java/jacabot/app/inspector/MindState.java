package jacabot.app.inspector;

import java.util.ArrayList;
import java.util.List;

/**
 * One agent's mind at one instant, as text: what Jason's mind inspector shows. Immutable, so the
 * web page and the step log read it from any thread; it is taken on the agent's own thread
 * ({@link MindProbe}), between reasoning cycles.
 *
 * @param timeMs the agent's clock (simulated time in experiments)
 * @param cycle reasoning cycles run so far
 * @param selections plans chosen since the previous state (the deliberation's trace)
 */
public record MindState(String agent, long seq, long timeMs, long cycle, List<Belief> beliefs, List<String> events,
        List<IntentionView> intentions, List<Selection> selections) {

    public MindState {
        beliefs = beliefs instanceof BeliefList shared ? shared : List.copyOf(beliefs); // immutable: kept as it is
        events = List.copyOf(events);
        intentions = List.copyOf(intentions);
        selections = List.copyOf(selections);
    }

    /** A belief: its literal without annotations, its sources and its other annotations. */
    public record Belief(String literal, List<String> sources, List<String> annots) {
        public Belief {
            sources = List.copyOf(sources);
            annots = List.copyOf(annots);
        }

        /** {@return the belief as Jason prints it} */
        public String text() {
            var all = new ArrayList<String>();
            sources.forEach(s -> all.add("source(" + s + ")"));
            all.addAll(annots);
            return all.isEmpty() ? literal : literal + all;
        }

        /** {@return whether it came from the environment (an observable property or percept)} */
        public boolean isPercept() {
            return sources.contains("percept");
        }
    }

    /** An intention: its stack of intended means, top first. */
    public record IntentionView(int id, String state, List<Means> stack) {
        public IntentionView {
            stack = List.copyOf(stack);
        }
    }

    /**
     * An intended means: the event it handles, the plan (label and head), the unifier, the step
     * about to run and the steps after it.
     */
    public record Means(String trigger, String plan, String unifier, String current, String rest) {
    }

    /** A plan chosen for an event, with the unifier that made it applicable. */
    public record Selection(long timeMs, long cycle, int intention, String event, String plan, String unifier) {
    }

    /** {@return whether beliefs, events or intentions differ from {@code o}} */
    public boolean sameMind(MindState o) {
        return o != null && beliefs.equals(o.beliefs) && events.equals(o.events) && intentions.equals(o.intentions)
                && selections.isEmpty();
    }
}
