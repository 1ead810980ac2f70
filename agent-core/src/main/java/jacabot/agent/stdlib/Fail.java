package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .fail} and {@code .fail(Annot, ...)}: fails the intention, with the given annotations. */
final class Fail extends DefaultInternalAction {
    Fail() {
        super(".fail", 0, 2147483647);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args.length == 0) {
            return false;
        }
        var annots = new java.util.ArrayList<Term>(java.util.List.of(args));
        boolean hasError = false;
        for (Term t : args) {
            if (t instanceof jacabot.agent.syntax.Literal l && l.functor().equals("error")) {
                hasError = true;
            }
        }
        if (!hasError) {
            annots.add(jacabot.agent.syntax.Literal.of("error", jacabot.agent.syntax.Literal.atom("ia_failed")));
        }
        throw new IaException("ia_failed", "", annots);
    }
}
