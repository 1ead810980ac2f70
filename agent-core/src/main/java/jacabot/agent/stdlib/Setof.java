package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.TreeSet;

/** {@code .setof(T, Query, L)}: as {@code .findall}, sorted and without duplicates. */
final class Setof extends DefaultInternalAction {
    Setof() {
        super(".setof", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var sorted = new TreeSet<Term>(Findall.solutions(ag, un, args[0], args[1]));
        return un.unifies(args[2], listOf(new ArrayList<>(sorted)));
    }
}
