package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/** {@code .empty(X)}: X is the empty list or the empty string (anything else, unbound too, fails). */
final class Empty extends DefaultInternalAction {
    Empty() {
        super(".empty", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof ListTerm.Empty || args[0] instanceof StringTerm s && s.value().isEmpty();
    }
}
