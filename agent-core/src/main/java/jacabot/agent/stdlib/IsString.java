package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/** {@code .string(X)}: X is a string. */
final class IsString extends DefaultInternalAction {
    IsString() {
        super(".string", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof StringTerm;
    }
}
