package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .set.create(S)}, {@code .map.create(M)}: a new empty set or map (fails when the argument is
 * bound to something else, as Jason's). Queues have {@link QueueCreate}, for their priority option.
 */
final class CollectionCreate extends DefaultInternalAction {
    private final boolean set;

    /** @param family set or map */
    CollectionCreate(String family) {
        super("." + family + ".create", 1, 1);
        this.set = family.equals("set");
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Object fresh = set ? new TermCollections.TermSet() : new TermCollections.TermMap();
        return un.unifies(args[0], new ObjectTerm(fresh));
    }
}
