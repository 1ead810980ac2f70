package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Var;
import jacabot.agent.syntax.ListTerm;
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
        // Jason's checks and words
        if (args[0] instanceof ListTerm && !(args[1] instanceof Var) && !(args[1] instanceof ListTerm)) {
            throw IaException.wrongArguments(name(), "last argument '" + args[1] + "' must be a list or a variable.");
        }
        if (!(args[0] instanceof ListTerm)) {
            if (!(args[1] instanceof Var) && !(args[1] instanceof StringTerm)) {
                throw IaException.wrongArguments(name(), "last argument '" + args[1] + "' must be a string or a variable.");
            }
            if (!(args[0] instanceof StringTerm s)) {
                throw IaException.wrongArguments(name(), "first argument of .reverse '" + args[0] + "' must be a string or a list");
            }
            return un.unifies(args[1], new StringTerm(new StringBuilder(s.value()).reverse().toString()));
        }
        var items = list(args[0]).elements(); // a new list
        Collections.reverse(items);
        return un.unifies(args[1], listOf(items));
    }
}
