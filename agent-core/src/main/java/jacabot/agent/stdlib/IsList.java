package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Term;

/** {@code .list(X)}: X is a list. */
final class IsList extends DefaultInternalAction {
    IsList() {
        super(".list", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof ListTerm;
    }
}
