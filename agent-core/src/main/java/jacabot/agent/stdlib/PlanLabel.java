package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;

/**
 * {@code .plan_label(Plan, Label)}: the plan of the library with that label, or the label of a
 * plan term; with both unbound, every plan of the library in turn.
 */
final class PlanLabel extends DefaultInternalAction {
    PlanLabel() {
        super(".plan_label", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof Var && !(args[1] instanceof Var)) {
            String label = args[1] instanceof Literal l ? l.functor() : text(args[1]);
            Plan p = ag.planLibrary().get(label);
            return p != null && un.unifies(args[0], Renamer.renameApart(new PlanTerm(p), ag));
        }
        if (args[0] instanceof PlanTerm pt && args[1] instanceof Var) {
            return pt.label() != null && un.unifies(args[1], pt.label());
        }
        var out = new ArrayList<Unifier>();
        for (Plan p : new ArrayList<>(ag.planLibrary().plans())) {
            Unifier c = un.copy();
            if (c.unifies(args[1], p.label()) && c.unifies(args[0], Renamer.renameApart(new PlanTerm(p), ag))) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
