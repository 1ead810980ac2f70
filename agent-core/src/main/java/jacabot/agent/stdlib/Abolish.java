package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Var;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;

/** {@code .abolish(B)}: removes every belief unifying B (with {@code -b} events). */
final class Abolish extends DefaultInternalAction {
    Abolish() {
        super(".abolish", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term b = args[0];
        if (!(b instanceof Literal) && !(b instanceof Var) && !(b instanceof AnnotatedVar)) {
            throw IaException.wrongArguments(name(), "first argument must be a literal or variable."); // Jason's words
        }
        var entries = b instanceof AnnotatedVar ? ag.beliefBase().all() : ag.beliefBase().candidates(literal(b));
        for (BeliefBase.Entry e : entries) {
            if (e.rule() == null && un.copy().unifies(b, e.literal())) {
                if (ag.beliefBase().removeEntry(e.literal())) {
                    ag.addExternalEvent(new Trigger(Trigger.Op.DEL, Trigger.Type.BELIEF, e.literal()));
                }
            }
        }
        return true;
    }
}
