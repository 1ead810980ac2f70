package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.Locale;

/**
 * {@code .lower_case(T, S)} and {@code .upper_case(T, S)}: S is the string T (any other term as
 * its text, e.g. {@code f(a)} gives {@code "F(A)"}) in lower or upper case, as Jason's.
 */
final class ChangeCase extends DefaultInternalAction {
    private final boolean upper;

    private ChangeCase(String name, boolean upper) {
        super(name, 2, 2);
        this.upper = upper;
    }

    static ChangeCase lower() {
        return new ChangeCase(".lower_case", false);
    }

    static ChangeCase upper() {
        return new ChangeCase(".upper_case", true);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String s = text(args[0]);
        // Locale.ROOT: the case of "i" must not depend on the machine's language
        return un.unifies(args[1], new StringTerm(upper ? s.toUpperCase(Locale.ROOT) : s.toLowerCase(Locale.ROOT)));
    }
}
