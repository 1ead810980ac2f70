package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.util.IllegalFormatException;

/** {@code .printf(Format, a, ...)}: Java's {@code String.format}; numbers are doubles, as in Jason. */
final class Printf extends DefaultInternalAction {
    Printf() {
        super(".printf", 1, 2147483647);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Object[] values = new Object[args.length - 1];
        for (int i = 1; i < args.length; i++) {
            Term t = args[i];
            if (t instanceof NumberTerm n) {
                values[i - 1] = n.value(); // a Double, as Jason passes it: %s prints 3.0, %d fails
            } else {
                values[i - 1] = text(t);
            }
        }
        String format = text(args[0]);
        try {
            ag.print(String.format(format, values));
        } catch (IllegalFormatException e) {
            throw IaException.wrongArguments(name(), e.getMessage());
        }
        return true;
    }
}
