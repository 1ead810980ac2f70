package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .map.put(M, K, V)}: K maps to V in M, replacing an earlier value (a new map when M is free, as Jason's). */
final class MapPut extends DefaultInternalAction {
    MapPut() {
        super(".map.put", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        TermCollections.map(name(), args[0], un).put(args[1], args[2]);
        return true;
    }
}
