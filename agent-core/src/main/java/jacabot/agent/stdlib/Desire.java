package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.Event;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayList;

/** {@code .desire(G)}: succeeds for each pending {@code +!G} event or intention pursuing G. */
final class Desire extends DefaultInternalAction {
    Desire() {
        super(".desire", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term g = args[0];
        var out = new ArrayList<Unifier>();
        for (Event e : ag.circumstance().eventList()) {
            Trigger t = e.trigger();
            Unifier c = un.copy();
            if (t.isAchieveGoal() && t.isAddition() && c.unifies(g, t.literal())) {
                out.add(c);
            }
        }
        Intend.addIntended(ag, g, un, out);
        for (Event e : ag.circumstance().pendingEvents().values()) {
            Trigger t = e.trigger();
            Unifier c = un.copy();
            if (t.isAchieveGoal() && t.isAddition() && c.unifies(g, t.literal())) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
