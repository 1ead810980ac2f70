package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .findall(T, Query, L)}: L is the list of T for every solution of Query. */
final class Findall extends DefaultInternalAction {
    Findall() {
        super(".findall", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new java.util.ArrayList<Term>();
        var it = ag.solver().solve(args[1], un);
        while (it.hasNext()) {
            out.add(it.next().apply(args[0]));
        }
        return un.unifies(args[2], listOf(out));
    }
}
