package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .kill_agent(Name)}: stops agent Name and takes it out of the system. */
final class KillAgent extends DefaultInternalAction {
    KillAgent() {
        super(".kill_agent", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String name = text(args[0]);
        if (name.equals(ag.name())) {
            ag.holdSelectedIntention();
        }
        return ag.arch().killAgent(name);
    }
}
