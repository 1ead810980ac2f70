package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.LinkedHashSet;

/**
 * {@code .namespace(NS)}: NS is a namespace of the agent's beliefs ({@code ns::b}); with NS
 * unbound, each of them in turn. Only the namespaces written as prefixes are known: the
 * directives {@code begin namespace} and {@code .namespace} declarations are not supported.
 */
final class Namespace extends DefaultInternalAction {
    Namespace() {
        super(".namespace", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var names = new LinkedHashSet<String>();
        for (BeliefBase.Entry e : ag.beliefBase().all()) {
            Literal l = e.rule() != null ? e.rule().head() : e.literal();
            int sep = l.functor().indexOf("::");
            if (sep > 0) {
                names.add(l.functor().substring(0, sep));
            }
        }
        var out = new ArrayList<Unifier>();
        for (String n : names) {
            Unifier c = un.copy();
            if (c.unifies(args[0], Literal.atom(n))) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
