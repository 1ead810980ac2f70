package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.Term;
import java.util.List;

/**
 * {@code .remove_plan(Label[, Source])}: Label is a label, a plan term or a list of them. As
 * Jason, it takes Source (default {@code self}) away from the plan's label and removes the plan
 * when no source is left; a plan without that source stays.
 */
final class RemovePlan extends DefaultInternalAction {
    RemovePlan() {
        super(".remove_plan", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term source = args.length > 1 ? args[1] : Literal.atom("self");
        List<Term> items = args[0] instanceof ListTerm l ? l.elements() : List.of(args[0]);
        for (Term t : items) {
            Term label = t instanceof PlanTerm p && p.label() != null ? p.label() : t;
            ag.planLibrary().removeSource(label instanceof Literal lit ? lit.functor() : text(label), source);
        }
        return true;
    }
}
