package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .get_src_info(L, R)}: R is literal L with {@code code_line(N)} and {@code code_src(F)}
 * annotations, as Jason's. Jason gives the place where L was written; ours is the place of the
 * step that calls the action, the same for a literal written in that step or bound by an earlier
 * step on the same line (Jason says line 1 of "" for a literal read from a string).
 */
final class GetSrcInfo extends DefaultInternalAction {
    GetSrcInfo() {
        super(".get_src_info", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof Literal l)) {
            return false;
        }
        Intention si = ag.circumstance().selectedIntention();
        BodyStep step = si == null || si.peek() == null ? null : si.peek().currentStep();
        if (step != null && step.source() != null) {
            l = l.addAnnot(Literal.of("code_src", new StringTerm(step.source().jasonFile())))
                    .addAnnot(Literal.of("code_line", new NumberTerm(step.source().line())));
        }
        return un.unifies(args[1], l);
    }
}
