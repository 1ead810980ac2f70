package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .stopMAS}: stops the multi-agent system. */
final class StopMAS extends DefaultInternalAction {
    StopMAS() {
        super(".stopMAS", 0, 2); // (Deadline, ExitCode): the exit code is accepted and not used
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        long deadline = args.length > 0 ? (long) number(args[0]) : 0;
        if (deadline > 0) {
            ag.arch().stopMAS(deadline);
            return true;
        }
        ag.stop();
        ag.holdSelectedIntention();
        ag.arch().stopMAS();
        return true;
    }
}
