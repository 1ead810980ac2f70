package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/** {@code .drop_desire(G)}: drops G as an intention and as a pending event. */
final class DropDesire extends DefaultInternalAction {
    DropDesire() {
        super(".drop_desire", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof Literal g)) {
            throw IaException.wrongArguments(name(), "first argument '" + args[0] + "' must be a literal or variable"); // Jason's words
        }
        for (Intention i : ag.intentionsFor(g, un)) {
            ag.dropIntention(i);
        }
        DropEvent.dropEvents(ag, g);
        return true;
    }
}
