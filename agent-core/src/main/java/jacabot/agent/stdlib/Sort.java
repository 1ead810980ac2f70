package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collections;

/** {@code .sort(L, S)}: S is L in the standard order of terms. */
final class Sort extends DefaultInternalAction {
    Sort() {
        super(".sort", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        checkFirstIsList(args);
        var items = list(args[0]).elements(); // a new list
        Collections.sort(items);
        return un.unifies(args[1], listOf(items));
    }
}
