package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.Collections;

/** {@code .reverse(L, R)}: a reversed list or string. */
final class Reverse extends DefaultInternalAction {
    Reverse() {
        super(".reverse", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof StringTerm s) {
            return un.unifies(args[1], new StringTerm(new StringBuilder(s.value()).reverse().toString()));
        }
        var items = list(args[0]).elements(); // a new list
        Collections.reverse(items);
        return un.unifies(args[1], listOf(items));
    }
}
