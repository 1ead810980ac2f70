package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/** {@code .delete(X, L, R)}: R is L without the elements unifying X (or without index X); also on strings. */
final class Delete extends DefaultInternalAction {
    Delete() {
        super(".delete", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[1] instanceof StringTerm s) {
            String what = text(args[0]);
            return un.unifies(args[2], new StringTerm(s.value().replace(what, "")));
        }
        List<Term> items = list(args[1]).elements();
        var out = new ArrayList<Term>();
        if (args[0] instanceof NumberTerm n) {
            int idx = (int) n.value();
            for (int i = 0; i < items.size(); i++) {
                if (i != idx) {
                    out.add(items.get(i));
                }
            }
        } else {
            // as Jason's: the pattern's variables keep what its first match bound them to, so
            // .delete(p(_), [p(1), q(2), p(3)], L) gives [q(2), p(3)]
            Unifier w = un.copy();
            for (Term t : items) {
                if (!w.unifies(args[0], t)) {
                    out.add(t);
                }
            }
        }
        return un.unifies(args[2], listOf(out));
    }
}
