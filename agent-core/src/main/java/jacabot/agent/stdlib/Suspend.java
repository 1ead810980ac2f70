package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .suspend(G)}: suspends the intentions pursuing G until {@code .resume(G)}; no argument: the current one. */
final class Suspend extends DefaultInternalAction {
    Suspend() {
        super(".suspend", 0, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return Suspensions.suspend(ag, args.length == 0 ? null : firstLiteral(args), un);
    }
}
