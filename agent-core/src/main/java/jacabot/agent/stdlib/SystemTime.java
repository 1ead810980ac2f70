package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .system_time(T)}: milliseconds on the agent's clock. */
final class SystemTime extends DefaultInternalAction {
    SystemTime() {
        super(".system_time", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], new NumberTerm(ag.clock().millis()));
    }
}
