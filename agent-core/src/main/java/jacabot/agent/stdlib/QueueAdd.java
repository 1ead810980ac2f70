package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collection;

/** {@code .queue.add(Q, T)} and {@code .queue.add_all(Q, L)}: adds to a queue, in the list's order. */
final class QueueAdd extends DefaultInternalAction {
    private final boolean all;

    QueueAdd(boolean all) {
        super(all ? ".queue.add_all" : ".queue.add", 2, 2);
        this.all = all;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var q = TermCollections.queue(name(), args[0]);
        if (!all) {
            q.add(args[1]);
            return true;
        }
        Collection<Term> items = TermCollections.elements(args[1]);
        if (items == null) {
            throw IaException.wrongArguments(name(), "'" + args[1] + "' is not a list");
        }
        q.addAll(items);
        return true;
    }
}
