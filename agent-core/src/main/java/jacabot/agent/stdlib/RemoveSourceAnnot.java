package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/**
 * {@code .remove_source_annot(T, R)}: R is the literal T (each literal of a list T) without its
 * {@code source(_)} annotations; other terms stay as they are.
 */
final class RemoveSourceAnnot extends DefaultInternalAction {
    RemoveSourceAnnot() {
        super(".remove_source_annot", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[1], strip(args[0]));
    }

    private static Term strip(Term t) {
        if (t instanceof ListTerm l) {
            var out = new ArrayList<Term>();
            for (Term e : l.elements()) {
                out.add(strip(e));
            }
            return listOf(out);
        }
        return t instanceof Literal l ? l.withoutSources() : t;
    }
}
