package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .stopMAS}: stops the multi-agent system. */
final class StopMAS extends DefaultInternalAction {
    StopMAS() {
        super(".stopMAS", 0, 2); // (Deadline, ExitCode) are accepted; the run stops at once
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        ag.stop();
        ag.holdSelectedIntention();
        ag.arch().stopMAS();
        return true;
    }
}
