package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/**
 * {@code .namespace(NS)}: NS is a namespace of the agent's beliefs and rules ({@code default}
 * among them); with NS unbound, each of them in turn, except local namespaces, which no
 * variable may take (as Jason's).
 */
final class Namespace extends DefaultInternalAction {
    Namespace() {
        super(".namespace", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new ArrayList<Unifier>();
        for (Term n : ag.beliefBase().namespaces()) {
            Unifier c = un.copy();
            if (c.unifies(args[0], n)) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
