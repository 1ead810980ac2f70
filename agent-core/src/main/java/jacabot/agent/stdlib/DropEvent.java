package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Circumstance;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;

/** {@code .drop_event(G)}: removes pending {@code +!G} events. */
final class DropEvent extends DefaultInternalAction {
    DropEvent() {
        super(".drop_event", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        dropEvents(ag, literal(args[0]));
        return true;
    }

    static void dropEvents(Agent ag, Literal g) {
        Circumstance c = ag.circumstance();
        for (Event e : c.eventList()) {
            Trigger t = e.trigger();
            if (t.isAchieveGoal() && t.isAddition() && ag.newUnifier().unifies(g, t.literal())) {
                c.removeEvent(e);
                if (e.intention() != null) {
                    ag.dropIntention(e.intention());
                }
            }
        }
    }
}
