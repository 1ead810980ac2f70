package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .nano_time(T)}: T is the JVM's nanosecond clock (for measuring intervals only). */
final class NanoTime extends DefaultInternalAction {
    NanoTime() {
        super(".nano_time", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], new NumberTerm(System.nanoTime()));
    }
}
