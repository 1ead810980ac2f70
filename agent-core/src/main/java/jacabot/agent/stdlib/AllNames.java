package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/** {@code .all_names(L)}: the names of every agent. */
final class AllNames extends DefaultInternalAction {
    AllNames() {
        super(".all_names", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var names = new ArrayList<Term>();
        for (String n : ag.arch().agentNames()) {
            names.add(Literal.atom(n));
        }
        return un.unifies(args[0], listOf(names));
    }
}
