package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.List;

/** {@code .remove_plan(Label)} or a list of labels: removes plans. */
final class RemovePlan extends DefaultInternalAction {
    RemovePlan() {
        super(".remove_plan", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        List<Term> items = args[0] instanceof ListTerm l ? l.elements() : List.of(args[0]);
        boolean all = true;
        for (Term t : items) {
            String label = t instanceof Literal lit ? lit.functor() : text(t);
            all &= ag.planLibrary().remove(label);
        }
        return all;
    }
}
