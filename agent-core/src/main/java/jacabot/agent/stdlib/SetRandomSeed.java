package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .set_random_seed(N)}: reseeds the agent's random generator. */
final class SetRandomSeed extends DefaultInternalAction {
    SetRandomSeed() {
        super(".set_random_seed", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        ag.setRandomSeed((long) number(args[0]));
        return true;
    }
}
