package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.InternalAction;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.util.NoSuchElementException;

/** {@code .range(X, Start, End[, Step])}: X takes each value from Start to End (backtracking). */
final class Range extends DefaultInternalAction {
    Range() {
        super(".range", 3, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String[] nth = {"", "second", "third", "fourth"};
        for (int i = 1; i < args.length; i++) {
            if (!(args[i] instanceof NumberTerm)) {
                throw IaException.wrongArguments(name(), nth[i] + " parameter ('" + args[i] + "') must be a number!");
            }
        }
        double start = number(args[1]);
        double end = number(args[2]);
        double step = args.length == 4 ? number(args[3]) : 1;
        if (step == 0) {
            throw IaException.wrongArguments(name(), "step 0");
        }
        // lazy: a for over a long range must not build every solution first
        return new Values(un, args[0], start, end, step);
    }

    /** The values from first to last, each bound to X by backtracking. */
    private static final class Values implements InternalAction.Solutions {
        private final Unifier un;
        private final Term x;
        private final double last;
        private final double by;
        private double v;
        private Unifier pending;
        private boolean looked;

        Values(Unifier un, Term x, double first, double last, double by) {
            this.un = un;
            this.x = x;
            this.v = first;
            this.last = last;
            this.by = by;
        }

        private boolean more() {
            return by > 0 ? v <= last : v >= last;
        }

        @Override
        public boolean nextInto(Unifier w) {
            while (more()) {
                boolean ok = w.unifies(x, new NumberTerm(v));
                v += by;
                if (ok) {
                    return true;
                }
            }
            return false;
        }

        @Override
        public boolean hasNext() {
            if (!looked) {
                looked = true;
                pending = null;
                while (pending == null && more()) {
                    Unifier c = un.copy();
                    if (c.unifies(x, new NumberTerm(v))) {
                        pending = c;
                    }
                    v += by;
                }
            }
            return pending != null;
        }

        @Override
        public Unifier next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            looked = false;
            return pending;
        }
    }
}
