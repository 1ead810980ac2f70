package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .map.remove(M, K, V)}: takes K out of M, V unified with its value; fails when K is not a key. */
final class MapRemove extends DefaultInternalAction {
    MapRemove() {
        super(".map.remove", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term value = TermCollections.map(name(), args[0]).remove(args[1]);
        return value != null && un.unifies(args[2], value);
    }
}
