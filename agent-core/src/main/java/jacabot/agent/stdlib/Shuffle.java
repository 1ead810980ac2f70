package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.Collections;

/**
 * {@code .shuffle(L, R)}: R is L in a random order. It draws from the agent's generator, as
 * {@code .random} does, so that {@code .set_random_seed} repeats a run (Jason's does not: its
 * order differs from run to run whatever the seed).
 */
final class Shuffle extends DefaultInternalAction {
    Shuffle() {
        super(".shuffle", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof ListTerm l)) {
            throw new IaException("wrong_arguments", "Wrong argument for internal action 'shuffle': first argument must be a list");
        }
        var items = new ArrayList<>(l.elements());
        Collections.shuffle(items, ag.random());
        return un.unifies(args[1], listOf(items));
    }
}
