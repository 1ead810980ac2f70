package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;

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
        // a snapshot: the plan asking for the next solution may have changed the map meanwhile
        List<Term> items = new ArrayList<>(keys ? map.keySet() : map.values());
        Unifier base = un.copy();
        Term x = args[1];
        return new Iterator<Unifier>() {
            private int i;
            private Unifier next;

            @Override
            public boolean hasNext() {
                while (next == null && i < items.size()) {
                    next = base.unifiedCopy(x, items.get(i++));
                }
                return next != null;
            }

            @Override
            public Unifier next() {
                if (!hasNext()) {
                    throw new NoSuchElementException();
                }
                Unifier n = next;
                next = null;
                return n;
            }
        };
    }
}
