package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collection;

/** {@code .member(X, L)}: X unifies with an element of L (backtracking). */
final class Member extends DefaultInternalAction {
    Member() {
        super(".member", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Collection<Term> items = TermCollections.elements(args[1]); // a list, or a set or queue of .set/.queue
        if (items == null) { // a map too: Jason's .member takes lists and sets only
            throw IaException.wrongArguments(name(), "second argument must be a list or a set");
        }
        return new EachUnifying(un, args[0], items);
    }
}
