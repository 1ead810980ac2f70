package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .set.clear(S)}, {@code .queue.clear(Q)} and {@code .map.clear(M)}: empty the collection. */
final class CollectionClear extends DefaultInternalAction {
    private final String family;

    /** @param family set, queue or map */
    CollectionClear(String family) {
        super("." + family + ".clear", 1, 1);
        this.family = family;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        switch (family) {
            case "set" -> TermCollections.set(name(), args[0]).clear();
            case "queue" -> TermCollections.queue(name(), args[0]).clear();
            default -> TermCollections.map(name(), args[0]).clear();
        }
        return true;
    }
}
