package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.List;

/** {@code .perceive}: perceives now, as the next sense would, so that the percepts are beliefs at once. */
final class Perceive extends DefaultInternalAction {
    Perceive() {
        super(".perceive", 0, 0);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        List<Literal> percepts = ag.arch().perceive();
        if (percepts != null) { // null: nothing changed since the last perception
            ag.beliefUpdate(percepts);
        }
        return true;
    }
}
