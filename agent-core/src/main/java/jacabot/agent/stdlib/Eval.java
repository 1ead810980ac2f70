package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/** {@code .eval(R, Formula)}: R is {@code true} if Formula is a logical consequence, else {@code false}. */
final class Eval extends DefaultInternalAction {
    Eval() {
        super(".eval", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        // the formula's own bindings are not kept (as Jason): only R is bound
        boolean holds = ag.solver().solve(args[1], un).hasNext();
        return un.unifies(args[0], Literal.atom(holds ? "true" : "false"));
    }
}
