package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .map.key(M, K)} and {@code .map.value(M, V)}: K (V) unifies with a key (value) of M, in the keys' order (backtracking). */
final class MapEntries extends DefaultInternalAction {
    private final boolean keys;

    MapEntries(boolean keys) {
        super(keys ? ".map.key" : ".map.value", 2, 2);
        this.keys = keys;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var map = TermCollections.map(name(), args[0]);
        return new EachUnifying(un, args[1], keys ? map.keySet() : map.values());
    }
}
