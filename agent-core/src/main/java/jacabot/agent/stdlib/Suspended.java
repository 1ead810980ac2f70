package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .suspended(G, R)}: G is suspended, for reason R. */
final class Suspended extends DefaultInternalAction {
    Suspended() {
        super(".suspended", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return Suspensions.suspended(ag, literal(args[0]), args[1], un);
    }
}
