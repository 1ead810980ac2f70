package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .count(Query, N)}: the number of solutions of Query. */
final class Count extends DefaultInternalAction {
    Count() {
        super(".count", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof NumberTerm || args[0] instanceof StringTerm || args[0] instanceof ListTerm) {
            throw IaException.wrongArguments(name(), "first argument must be a formula"); // Jason's words
        }
        int n = 0;
        var it = ag.solver().solve(args[0], un);
        while (it.hasNext()) {
            it.next();
            n++;
        }
        return un.unifies(args[1], new NumberTerm(n));
    }
}
