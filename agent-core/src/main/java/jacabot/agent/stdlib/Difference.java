package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.TreeSet;

/** {@code .difference(A, B, D)}: the sorted set difference. */
final class Difference extends DefaultInternalAction {
    Difference() {
        super(".difference", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        checkListOperands(args);
        var set = new TreeSet<Term>(list(args[0]).elements());
        set.removeAll(new TreeSet<Term>(list(args[1]).elements()));
        return un.unifies(args[2], listOf(new ArrayList<>(set)));
    }
}
