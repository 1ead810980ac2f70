package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collection;

/** {@code .set.add(S, T)} and {@code .set.add_all(S, L)}: adds to a set (a new one when S is free). */
final class SetAdd extends DefaultInternalAction {
    private final boolean all;

    SetAdd(boolean all) {
        super(all ? ".set.add_all" : ".set.add", 2, 2);
        this.all = all;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var set = TermCollections.set(name(), args[0], un);
        if (!all) {
            set.add(args[1]);
            return true;
        }
        Collection<Term> items = TermCollections.elements(args[1]);
        if (items == null) {
            throw IaException.wrongArguments(name(), "'" + args[1] + "' is not a list");
        }
        set.addAll(items);
        return true;
    }
}
