package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.SourceInfo;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .get_src_info(L, R)}: R is literal L with {@code code_line(N)} and {@code code_src(F)}
 * annotations, as Jason's: the place where L was written, wherever it went since (a variable, a
 * sub-goal, the belief base, a message); {@code code_src("")} and line 1 for a literal read from a
 * string at run time, {@code no_code} for one made at run time ({@code =..}). Annotations L
 * already has are kept.
 */
final class GetSrcInfo extends DefaultInternalAction {
    private static final Literal NO_CODE = Literal.atom("no_code");

    GetSrcInfo() {
        super(".get_src_info", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof Literal l)) {
            return false;
        }
        SourceInfo src = l.src();
        if (l.getAnnot("code_src") == null) {
            l = l.addAnnot(Literal.of("code_src", src == null ? NO_CODE : new StringTerm(src.jasonSrc())));
        }
        if (l.getAnnot("code_line") == null) {
            l = l.addAnnot(Literal.of("code_line", src == null ? NO_CODE : new NumberTerm(src.line())));
        }
        return un.unifies(args[1], l);
    }
}
