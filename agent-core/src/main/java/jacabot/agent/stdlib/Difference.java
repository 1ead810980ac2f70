package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .difference(A, B, D)}: the sorted set difference. */
final class Difference extends DefaultInternalAction {
    Difference() {
        super(".difference", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var set = new java.util.TreeSet<Term>(list(args[0]).elements());
        set.removeAll(new java.util.TreeSet<Term>(list(args[1]).elements()));
        return un.unifies(args[2], listOf(new java.util.ArrayList<>(set)));
    }
}
