package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/** {@code .nth(I, L, X)}: X is the element at index I (from 0) of a list or string. */
final class Nth extends DefaultInternalAction {
    Nth() {
        super(".nth", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[1] instanceof StringTerm s) {
            int i = (int) number(args[0]);
            if (i < 0 || i >= s.value().length()) {
                throw IaException.wrongArguments(name(), "index " + i + " out of bounds");
            }
            return un.unifies(args[2], new StringTerm(s.value().substring(i, i + 1)));
        }
        List<Term> items = list(args[1]).elements();
        if (args[0] instanceof NumberTerm n) {
            int i = (int) n.value();
            if (i < 0 || i >= items.size()) {
                throw IaException.wrongArguments(name(), "index " + i + " out of bounds");
            }
            return un.unifies(args[2], items.get(i));
        }
        var out = new ArrayList<Unifier>();
        for (int i = 0; i < items.size(); i++) {
            Unifier c = un.copy();
            if (c.unifies(args[0], new NumberTerm(i)) && c.unifies(args[2], items.get(i))) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
