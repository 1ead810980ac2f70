package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/** {@code .atom(X)}: X is an atom. */
final class IsAtom extends DefaultInternalAction {
    IsAtom() {
        super(".atom", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof Literal l && l.isAtom();
    }
}
