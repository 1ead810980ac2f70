package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.util.Iterator;
import java.util.List;

/**
 * {@code .random(X)}: a number in [0,1); {@code .random(X, N)}: N such numbers, one solution each
 * (N = 0: without end); {@code .random(L, X[, N])}: elements of L drawn at random. All draw from
 * the agent's generator, as {@code math.random} (so {@code .set_random_seed} repeats a run).
 */
final class Random extends DefaultInternalAction {
    Random() {
        super(".random", 1, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args.length == 1) {
            return un.unifies(args[0], new NumberTerm(ag.random().nextDouble()));
        }
        List<Term> items;
        int max;
        if (args[0] instanceof ListTerm l) {
            items = l.elements();
            if (items.isEmpty()) {
                return false;
            }
            max = args.length == 2 ? 1 : (int) number(args[2]);
        } else {
            items = null;
            max = (int) number(args[1]);
        }
        return new Iterator<Unifier>() {
            private int n;

            @Override
            public boolean hasNext() {
                return (n < max || max == 0) && !ag.isStopped();
            }

            @Override
            public Unifier next() {
                n++;
                Unifier c = un.copy();
                if (items == null) {
                    c.unifies(args[0], new NumberTerm(ag.random().nextDouble()));
                } else {
                    c.unifies(args[1], items.get(ag.random().nextInt(items.size())));
                }
                return c;
            }
        };
    }
}
