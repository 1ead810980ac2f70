package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .join(Fork)}, placed by {@code .fork} at the end of each branch: an and-fork goes on
 * when its last branch joins, an or-fork when its first does (dropping the others).
 */
final class Join extends DefaultInternalAction {
    Join() {
        super(".join", 1, 1);
    }

    @Override
    public boolean suspendsIntention() {
        return true;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof ObjectTerm o) || !(o.value() instanceof Fork.Branches b)) {
            throw IaException.wrongArguments(name(), "'" + args[0] + "' is not a fork (.join is placed by .fork)");
        }
        Intention si = ag.circumstance().selectedIntention();
        b.toJoin--;
        b.running.remove(si);
        if (b.and && b.toJoin > 0) {
            ag.holdSelectedIntention(); // waits, and ends, here: the last branch goes on
            return true;
        }
        if (!b.and) {
            for (Intention other : b.running) {
                ag.dropIntention(other);
            }
            b.running.clear();
        }
        si.peek().removeCurrentStep();
        ag.circumstance().addRunningIntention(si);
        return true;
    }
}
