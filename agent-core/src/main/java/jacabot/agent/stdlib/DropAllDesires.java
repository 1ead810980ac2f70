package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .drop_all_desires}: drops every event and every intention but the running one. */
final class DropAllDesires extends DefaultInternalAction {
    DropAllDesires() {
        super(".drop_all_desires", 0, 0);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        DropAllIntentions.dropAllButCurrent(ag);
        Circumstance c = ag.circumstance();
        for (Event e : c.eventList()) {
            c.removeEvent(e);
        }
        return true;
    }
}
