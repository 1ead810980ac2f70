package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.List;

/** {@code .max(L, X)}: the greatest element in the standard order. */
final class Max extends DefaultInternalAction {
    Max() {
        super(".max", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        List<Term> items = list(args[0]).elements();
        if (items.isEmpty()) {
            return false;
        }
        return un.unifies(args[1], java.util.Collections.max(items));
    }
}
