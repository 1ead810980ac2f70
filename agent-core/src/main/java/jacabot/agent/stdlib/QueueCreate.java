package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayDeque;
import java.util.Queue;
import java.util.concurrent.PriorityBlockingQueue;

/** {@code .queue.create(Q[, priority])}: a new queue, first in first out, or by the standard order of terms. */
final class QueueCreate extends DefaultInternalAction {
    QueueCreate() {
        super(".queue.create", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean priority = args.length == 2 && args[1].toString().equals("priority");
        Queue<Term> q = priority ? new PriorityBlockingQueue<>() : new ArrayDeque<>();
        return un.unifies(args[0], new ObjectTerm(q));
    }
}
