package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .drop_all_intentions}: drops every intention but the one running it. */
final class DropAllIntentions extends DefaultInternalAction {
    DropAllIntentions() {
        super(".drop_all_intentions", 0, 0);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        dropAllButCurrent(ag);
        return true;
    }

    static void dropAllButCurrent(Agent ag) {
        Circumstance c = ag.circumstance();
        Intention current = c.selectedIntention();
        for (Intention i : c.allIntentions()) {
            if (i != current) {
                ag.dropIntention(i);
            }
        }
    }
}
