package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/** {@code .length(L, N)}: the length of a list or a string. */
final class Length extends DefaultInternalAction {
    Length() {
        super(".length", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof StringTerm s) {
            return un.unifies(args[1], new NumberTerm(s.value().length()));
        }
        if (args[0] instanceof jacabot.agent.syntax.ListTerm l) {
            return un.unifies(args[1], new NumberTerm(l.elements().size()));
        }
        return false; // as Jason: neither a list nor a string, the action just fails
    }
}
