package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.TreeSet;

/** {@code .intersection(A, B, I)}: the sorted set intersection. */
final class Intersection extends DefaultInternalAction {
    Intersection() {
        super(".intersection", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        checkListOperands(args);
        var set = new TreeSet<Term>(list(args[0]).elements());
        set.retainAll(new TreeSet<Term>(list(args[1]).elements()));
        return un.unifies(args[2], listOf(new ArrayList<>(set)));
    }
}
