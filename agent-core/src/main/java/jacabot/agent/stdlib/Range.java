package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .range(X, Start, End[, Step])}: X takes each value from Start to End (backtracking). */
final class Range extends DefaultInternalAction {
    Range() {
        super(".range", 3, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        double start = number(args[1]);
        double end = number(args[2]);
        double step = args.length == 4 ? number(args[3]) : 1;
        if (step == 0) {
            throw IaException.wrongArguments(name(), "step 0");
        }
        // lazy: a for over a long range must not build every solution first
        final double first = start;
        final double last = end;
        final double by = step;
        return new java.util.Iterator<Unifier>() {
            private double v = first;
            private Unifier next = advance();

            private Unifier advance() {
                while (by > 0 ? v <= last : v >= last) {
                    Unifier c = un.copy();
                    boolean ok = c.unifies(args[0], new NumberTerm(v));
                    v += by;
                    if (ok) {
                        return c;
                    }
                }
                return null;
            }

            @Override
            public boolean hasNext() {
                return next != null;
            }

            @Override
            public Unifier next() {
                if (next == null) {
                    throw new java.util.NoSuchElementException();
                }
                Unifier out = next;
                next = advance();
                return out;
            }
        };
    }
}
