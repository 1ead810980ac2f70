package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .setof(T, Query, L)}: as {@code .findall}, sorted and without duplicates. */
final class Setof extends DefaultInternalAction {
    Setof() {
        super(".setof", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new java.util.TreeSet<Term>();
        var it = ag.solver().solve(args[1], un);
        while (it.hasNext()) {
            out.add(it.next().apply(args[0]));
        }
        return un.unifies(args[2], listOf(new java.util.ArrayList<>(out)));
    }
}
