package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;

/**
 * {@code .signal({+e})}: posts the trigger as an external event, as is (no source added, no
 * belief or goal changed): plans for it run in a new intention.
 */
final class Signal extends DefaultInternalAction {
    Signal() {
        super(".signal", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof TriggerTerm tt)) { // Jason posts an event without trigger and its cycle fails
            throw IaException.wrongArguments(name(), "'" + args[0] + "' is not a trigger such as {+e}");
        }
        ag.addExternalEvent(tt.trigger());
        return true;
    }
}
