package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/** {@code .add_annot(L, A, R)}: R is L (or each literal of list L) with annotation A. */
final class AddAnnot extends DefaultInternalAction {
    AddAnnot() {
        super(".add_annot", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof ListTerm l) {
            var out = new ArrayList<Term>();
            for (Term t : l.elements()) {
                out.add(t instanceof Literal lit ? lit.addAnnot(args[1]) : t);
            }
            return un.unifies(args[2], listOf(out));
        }
        return un.unifies(args[2], literal(args[0]).addAnnot(args[1]));
    }
}
