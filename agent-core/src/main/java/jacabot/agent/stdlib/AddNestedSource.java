package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/**
 * {@code .add_nested_source(T, S, R)}: R is the literal T (each literal of a list T) with the
 * source {@code source(S)}, its former sources nested in it ({@code b[source(t)]} gives
 * {@code b[source(S)[source(t)]]}), as told beliefs are stored. Other terms stay as they are.
 */
final class AddNestedSource extends DefaultInternalAction {
    AddNestedSource() {
        super(".add_nested_source", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[2], nest(args[0], Literal.of("source", args[1])));
    }

    private static Term nest(Term t, Literal source) {
        if (t instanceof ListTerm l) {
            var out = new ArrayList<Term>();
            for (Term e : l.elements()) {
                out.add(nest(e, source));
            }
            return listOf(out);
        }
        if (!(t instanceof Literal l)) {
            return t;
        }
        var former = new ArrayList<Term>();
        for (Term a : l.annots()) {
            if (a instanceof Literal al && al.functor().equals("source") && al.arity() == 1) {
                former.add(a);
            }
        }
        return l.withoutSources().addAnnot(former.isEmpty() ? source : source.withAnnots(former));
    }
}
