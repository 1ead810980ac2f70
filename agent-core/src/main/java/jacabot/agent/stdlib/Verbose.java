package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .verbose(N)}: sets the agent's verbosity (0 warnings only, 1 information, 2 details); Jason ignores further arguments. */
final class Verbose extends DefaultInternalAction {
    Verbose() {
        super(".verbose", 1, Integer.MAX_VALUE);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        ag.setVerbosity((int) number(args[0]));
        return true;
    }
}
