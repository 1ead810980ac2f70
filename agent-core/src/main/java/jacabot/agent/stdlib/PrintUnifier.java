package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/**
 * {@code .print_unifier}: prints each bound variable of the intention as {@code X=value}, then
 * {@code done}, as Jason does; like Jason it ignores any argument, and a variable bound only to
 * a free variable prints as {@code X=null}.
 */
final class PrintUnifier extends DefaultInternalAction {
    PrintUnifier() {
        super(".print_unifier", 0, Integer.MAX_VALUE);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        for (Var v : un.bindings().keySet()) {
            Term value = un.apply(v);
            ag.print(v + "=" + (value instanceof Var ? "null" : value));
        }
        ag.print("done");
        return true;
    }
}
