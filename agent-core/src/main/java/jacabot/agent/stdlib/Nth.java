package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;

/** {@code .nth(I, L, X)}: X is the element at index I (from 0) of a list or string. */
final class Nth extends DefaultInternalAction {
    Nth() {
        super(".nth", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        // Jason's checks and words
        if (!(args[0] instanceof NumberTerm) && !(args[0] instanceof Var)) {
            throw IaException.wrongArguments(name(), "the first argument should be numeric or a variable -- not '" + args[0] + "'.");
        }
        if (!(args[1] instanceof ListTerm) && !(args[1] instanceof StringTerm)) {
            throw IaException.wrongArguments(name(), "the second argument should be a list or string and not '" + args[1] + "'.");
        }
        if (args[1] instanceof StringTerm s) {
            int i = (int) number(args[0]);
            if (i < 0 || i >= s.value().length()) {
                throw outOfBounds(i, s.value().length());
            }
            return un.unifies(args[2], new StringTerm(s.value().substring(i, i + 1)));
        }
        List<Term> items = list(args[1]).elements();
        if (args[0] instanceof NumberTerm n) {
            int i = (int) n.value();
            if (i < 0 || i >= items.size()) {
                throw outOfBounds(i, items.size());
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

    private static IaException outOfBounds(int i, int size) {
        return new IaException("internal_action", "nth: index " + i + " is out of bounds (" + size + ")");
    }
}
