package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/** {@code .internal_action(T)}: whether T is a call of an internal action the agent knows ({@code .print(x)}, not {@code ".print"}). */
final class InternalActionCheck extends DefaultInternalAction {
    InternalActionCheck() {
        super(".internal_action", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0] instanceof Literal l && l.isInternalAction() && ag.internalAction(l.functor()) != null;
    }
}
