package jacabot.agent.stdlib;

import java.util.ArrayList;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .fail} and {@code .fail(Annot, ...)}: fails the intention. As Jason's, arguments go to the
 * failure event next to {@code error(internal_action)} and {@code error_msg(M)}, M being the first
 * {@code error_msg(M)} argument's text (which is not repeated) or {@code "fail"}; an
 * {@code error(E)} argument is kept beside {@code error(internal_action)}.
 */
final class Fail extends DefaultInternalAction {
    Fail() {
        super(".fail", 0, Integer.MAX_VALUE);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args.length == 0) {
            return false;
        }
        Term msgArg = null;
        String msg = "fail";
        for (Term t : args) {
            if (t instanceof Literal l && l.functor().equals("error_msg") && l.arity() == 1) {
                msgArg = t;
                msg = l.arg(0) instanceof StringTerm s ? s.value() : l.arg(0).toString();
                break;
            }
        }
        var annots = new ArrayList<Term>();
        annots.add(Literal.of("error", Literal.atom("internal_action")));
        annots.add(Literal.of("error_msg", new StringTerm(msg)));
        for (Term t : args) {
            if (t != msgArg) {
                annots.add(t);
            }
        }
        throw new IaException("internal_action", msg, annots);
    }
}
