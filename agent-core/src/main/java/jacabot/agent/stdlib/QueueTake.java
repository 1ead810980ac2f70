package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .queue.head(Q, T)} looks at the first element, {@code .queue.remove(Q, T)} takes it; both fail on an empty queue. */
final class QueueTake extends DefaultInternalAction {
    private final boolean remove;

    QueueTake(boolean remove) {
        super(remove ? ".queue.remove" : ".queue.head", 2, 2);
        this.remove = remove;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var q = TermCollections.queue(name(), args[0]);
        Term first = remove ? q.poll() : q.peek();
        return first != null && un.unifies(args[1], first);
    }
}
