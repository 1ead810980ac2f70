package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/** {@code .findall(T, Query, L)}: L is the list of T for every solution of Query. */
final class Findall extends DefaultInternalAction {
    Findall() {
        super(".findall", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[2], listOf(solutions(ag, un, args[0], args[1])));
    }

    /** {@return {@code template} instantiated by every solution of {@code query}, in order} */
    static List<Term> solutions(Agent ag, Unifier un, Term template, Term query) {
        var out = new ArrayList<Term>();
        var it = ag.solver().solve(query, un);
        while (it.hasNext()) {
            out.add(it.next().apply(template));
        }
        return out;
    }
}
