package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.util.List;

/** {@code .random(X)}: X in [0,1); {@code .random(List, X)}: a random element (backtracks over up to N draws with a third argument). */
final class Random extends DefaultInternalAction {
    Random() {
        super(".random", 1, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args.length == 1) {
            return un.unifies(args[0], new NumberTerm(ag.random().nextDouble()));
        }
        if (args[0] instanceof ListTerm l) {
            List<Term> items = l.elements();
            if (items.isEmpty()) {
                return false;
            }
            return un.unifies(args[1], items.get(ag.random().nextInt(items.size())));
        }
        return un.unifies(args[0], new NumberTerm(ag.random().nextDouble() * number(args[1])));
    }
}
