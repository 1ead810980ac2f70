package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .drop_intention(G)}: drops every intention pursuing G, without failure plans; no argument: the current one. */
final class DropIntention extends DefaultInternalAction {
    DropIntention() {
        super(".drop_intention", 0, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Intention current = ag.circumstance().selectedIntention();
        if (args.length == 0) {
            ag.dropIntention(current);
            return true;
        }
        for (Intention i : ag.intentionsFor(literal(args[0]), un)) {
            ag.dropIntention(i);
        }
        return true;
    }
}
