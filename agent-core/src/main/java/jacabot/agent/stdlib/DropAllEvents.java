package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .drop_all_events}: removes every pending event. */
final class DropAllEvents extends DefaultInternalAction {
    DropAllEvents() {
        super(".drop_all_events", 0, 0);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Circumstance c = ag.circumstance();
        for (Event e : c.eventList()) {
            c.removeEvent(e);
        }
        return true;
    }
}
