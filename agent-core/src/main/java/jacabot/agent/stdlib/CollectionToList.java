package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

import java.util.ArrayList;

/** {@code .set.to_list(S, L)} and {@code .queue.to_list(Q, L)}: L lists the elements in their iteration order (a priority queue's is its heap's, as in Jason). */
final class CollectionToList extends DefaultInternalAction {
    private final boolean queue;

    CollectionToList(boolean queue) {
        super(queue ? ".queue.to_list" : ".set.to_list", 2, 2);
        this.queue = queue;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var items = queue ? TermCollections.queue(name(), args[0]) : TermCollections.set(name(), args[0]);
        return un.unifies(args[1], listOf(new ArrayList<>(items)));
    }
}
