package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .println(a, ...)}: as {@code .print} (Jason's console ends every line anyway). */
final class Println extends DefaultInternalAction {
    Println() {
        super(".println", 0, 2147483647);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return Print.printConcatenated(ag, args);
    }
}
