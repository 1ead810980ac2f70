package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;

import java.util.ArrayDeque;
import java.util.Queue;
import java.util.concurrent.PriorityBlockingQueue;

/** {@code .set.copy(S, C)}, {@code .queue.copy(Q, C)} and {@code .map.copy(M, C)}: C is a new collection with the same elements, changed apart. */
final class CollectionCopy extends DefaultInternalAction {
    private final String family;

    /** @param family set, queue or map */
    CollectionCopy(String family) {
        super("." + family + ".copy", 2, 2);
        this.family = family;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Object copy = switch (family) {
            case "set" -> new TermCollections.TermSet(TermCollections.set(name(), args[0]));
            case "queue" -> copy(TermCollections.queue(name(), args[0]));
            default -> new TermCollections.TermMap(TermCollections.map(name(), args[0]));
        };
        return un.unifies(args[1], new ObjectTerm(copy));
    }

    /** A priority queue stays one (its heap copied as it is), a plain queue keeps its order. */
    private static Queue<Term> copy(Queue<Term> q) {
        return q instanceof PriorityBlockingQueue<Term> p ? new PriorityBlockingQueue<>(p) : new ArrayDeque<>(q);
    }
}
