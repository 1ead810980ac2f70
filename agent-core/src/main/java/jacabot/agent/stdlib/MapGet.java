package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .map.get(M, K, V[, Default])}: V is K's value in M, or Default when K is not a key (without Default, the action fails). */
final class MapGet extends DefaultInternalAction {
    MapGet() {
        super(".map.get", 3, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term value = TermCollections.map(name(), args[0]).get(args[1]);
        if (value == null && args.length == 4) {
            value = args[3];
        }
        return value != null && un.unifies(args[2], value);
    }
}
