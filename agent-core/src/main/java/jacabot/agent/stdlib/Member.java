package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .member(X, L)}: X unifies with an element of L (backtracking). */
final class Member extends DefaultInternalAction {
    Member() {
        super(".member", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new java.util.ArrayList<Unifier>();
        var items = TermCollections.elements(args[1]); // a list, or a set or queue of .set/.queue
        if (items == null) {
            items = list(args[1]).elements();
        }
        for (Term t : items) {
            Unifier c = un.copy();
            if (c.unifies(args[0], t)) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
