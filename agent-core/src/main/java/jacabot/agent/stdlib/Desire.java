package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code .desire(G)} and {@code .desire(G, Id)}: succeeds for each {@code +!G} event or intention
 * pursuing G (backtracking), in Jason's order: the event selected in this cycle, the events, the
 * suspended events, then the intentions, suspended ones included. Id is the number of the event's
 * intention (an event of no intention matches any Id) or of the intention.
 */
final class Desire extends DefaultInternalAction {
    Desire() {
        super(".desire", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term g = args[0];
        Term id = args.length == 2 ? args[1] : null;
        var out = new ArrayList<Unifier>();
        Event selected = ag.circumstance().selectedEvent();
        if (selected != null) {
            addIfDesired(selected, g, id, un, out);
        }
        for (Event e : ag.circumstance().eventList()) {
            addIfDesired(e, g, id, un, out);
        }
        for (Event e : ag.circumstance().pendingEvents().values()) {
            addIfDesired(e, g, id, un, out);
        }
        Intend.addIntended(ag, g, id, un, true, out);
        return out.iterator();
    }

    private static void addIfDesired(Event e, Term g, Term id, Unifier un, List<Unifier> out) {
        Trigger t = e.trigger();
        Unifier c = un.copy();
        if (t.isAchieveGoal() && t.isAddition() && c.unifies(g, t.literal())
                && (id == null || e.intention() == null || c.unifies(id, new NumberTerm(e.intention().id())))) {
            out.add(c);
        }
    }
}
