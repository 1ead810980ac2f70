package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/** {@code .version(V)}: V is the string of the Jason version whose language this interpreter runs. */
final class Version extends DefaultInternalAction {
    static final String JASON = "3.2.0";

    Version() {
        super(".version", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], new StringTerm(JASON));
    }
}
