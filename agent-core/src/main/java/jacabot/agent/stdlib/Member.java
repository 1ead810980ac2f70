package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collection;
import java.util.Iterator;
import java.util.NoSuchElementException;

/** {@code .member(X, L)}: X unifies with an element of L (backtracking). */
final class Member extends DefaultInternalAction {
    Member() {
        super(".member", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Collection<Term> items = TermCollections.elements(args[1]); // a list, or a set or queue of .set/.queue
        if (items == null) { // a map too: Jason's .member takes lists and sets only
            throw IaException.wrongArguments(name(), "'" + args[1] + "' is not a list, a set or a queue");
        }
        Term[] elements = items.toArray(new Term[0]);
        Unifier base = un.copy();
        Term x = args[0];
        // a solution's unifier is made when it is asked for (a plan body takes the first only), from
        // the elements and the bindings of the call: a for loop's body may change both meanwhile
        return new Iterator<Unifier>() {
            private int i;
            private Unifier next;

            @Override
            public boolean hasNext() {
                while (next == null && i < elements.length) {
                    next = base.unifiedCopy(x, elements[i++]);
                }
                return next != null;
            }

            @Override
            public Unifier next() {
                if (!hasNext()) {
                    throw new NoSuchElementException();
                }
                Unifier n = next;
                next = null;
                return n;
            }
        };
    }
}
