package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .resume(G)}: resumes the intentions suspended for G. */
final class Resume extends DefaultInternalAction {
    Resume() {
        super(".resume", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return Suspensions.resume(ag, firstLiteral(args), un);
    }
}
