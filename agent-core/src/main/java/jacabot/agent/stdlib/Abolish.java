package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
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
        Literal b = literal(args[0]);
        for (BeliefBase.Entry e : ag.beliefBase().candidates(b)) {
            if (e.rule() == null && un.copy().unifies(b, e.literal())) {
                if (ag.beliefBase().removeEntry(e.literal())) {
                    ag.addExternalEvent(new Trigger(Trigger.Op.DEL, Trigger.Type.BELIEF, e.literal()));
                }
            }
        }
        return true;
    }
}
