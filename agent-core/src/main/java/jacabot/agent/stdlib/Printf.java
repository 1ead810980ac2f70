package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;

/** {@code .printf(Format, a, ...)}: Java's {@code String.format}; integral numbers format as %d too. */
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
                values[i - 1] = n.value() == Math.rint(n.value()) ? (Object) (long) n.value() : (Object) n.value();
            } else {
                values[i - 1] = text(t);
            }
        }
        String format = text(args[0]);
        try {
            ag.print(String.format(format, values));
        } catch (java.util.IllegalFormatException e) {
            for (int i = 0; i < values.length; i++) {
                if (values[i] instanceof Long l) {
                    values[i] = l.doubleValue();
                }
            }
            try {
                ag.print(String.format(format, values));
            } catch (java.util.IllegalFormatException e2) {
                throw IaException.wrongArguments(name(), e2.getMessage());
            }
        }
        return true;
    }
}
