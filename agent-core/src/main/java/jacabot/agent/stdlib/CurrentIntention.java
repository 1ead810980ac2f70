package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.semantics.Unifier;

/**
 * {@code .current_intention(intention(Id, Stack))}: deprecated in Jason, which warns and still
 * answers; {@code .intention(Id, _, Stack, current)} is its replacement.
 */
final class CurrentIntention extends DefaultInternalAction {
    CurrentIntention() {
        super(".current_intention", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        ag.warn(".current_intention( intention(I,S) ) was replaced by .intention(I,_,S,current)");
        Circumstance c = ag.circumstance();
        Intention i = c.selectedIntention() != null ? c.selectedIntention()
                : c.selectedEvent() == null ? null : c.selectedEvent().intention();
        if (i == null) {
            return false;
        }
        Term stack = IntentionIa.stack(i, ag); // as Jason's, the same term as .intention's
        return un.unifies(args[0], Literal.of("intention", new NumberTerm(i.id()), stack));
    }
}
