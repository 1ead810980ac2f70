package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.Collection;

/** {@code .length(L, N)}: the length of a list, a string, or a set, queue or map. */
final class Length extends DefaultInternalAction {
    Length() {
        super(".length", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof StringTerm s) {
            return un.unifies(args[1], new NumberTerm(s.value().length()));
        }
        if (args[0] instanceof ListTerm l) {
            return un.unifies(args[1], new NumberTerm(l.elements().size()));
        }
        if (args[0] instanceof ObjectTerm o) { // a set, queue or map of .set/.queue/.map
            if (o.value() instanceof Collection<?> c) {
                return un.unifies(args[1], new NumberTerm(c.size()));
            }
            if (o.value() instanceof TermCollections.TermMap m) {
                return un.unifies(args[1], new NumberTerm(m.size()));
            }
        }
        return false; // as Jason: neither a list nor a string, the action just fails
    }
}
