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
        var out = new java.util.ArrayList<Unifier>();
        for (double v = start; step > 0 ? v <= end : v >= end; v += step) {
            Unifier c = un.copy();
            if (c.unifies(args[0], new NumberTerm(v))) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
