package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .set.remove(S, T)}: T is no longer in S (succeeds also when it was not there). */
final class SetRemove extends DefaultInternalAction {
    SetRemove() {
        super(".set.remove", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        TermCollections.set(name(), args[0]).remove(args[1]);
        return true;
    }
}
