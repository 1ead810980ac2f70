package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .number(X)}: X is a number. */
final class IsNumber extends DefaultInternalAction {
    IsNumber() {
        super(".number", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof NumberTerm;
    }
}
