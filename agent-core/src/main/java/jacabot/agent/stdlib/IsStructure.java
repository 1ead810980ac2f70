package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/**
 * {@code .structure(X)}: X is a structure: a list, a literal that is not an atom, or an atom
 * written as an operand of a relational expression ({@code Z = a; .structure(Z)}), as in Jason.
 */
final class IsStructure extends DefaultInternalAction {
    IsStructure() {
        super(".structure", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof ListTerm
                || args[0] instanceof Literal l && (!l.isAtom() || l.operandAtom());
    }
}
