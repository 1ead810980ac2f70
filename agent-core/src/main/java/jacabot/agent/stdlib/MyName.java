package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/** {@code .my_name(N)}: the agent's name. */
final class MyName extends DefaultInternalAction {
    MyName() {
        super(".my_name", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], Literal.atom(ag.name()));
    }
}
