package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .ground(X)}: X is ground. */
final class IsGround extends DefaultInternalAction {
    IsGround() {
        super(".ground", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return args[0].isGround();
    }
}
