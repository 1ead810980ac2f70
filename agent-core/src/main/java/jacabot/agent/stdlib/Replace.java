package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/**
 * {@code .replace(S, Regex, By, R)}: R is S with every match of the (Java) regular expression
 * replaced by By, where {@code $1} refers to a group, as Jason's. Jason accepts strings only and
 * fails with {@code error(unknown)} for anything else or a bad expression; so does this one, with
 * a message that says why.
 */
final class Replace extends DefaultInternalAction {
    Replace() {
        super(".replace", 4, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        for (int i = 0; i < 3; i++) {
            if (!(args[i] instanceof StringTerm)) {
                throw new IaException("unknown", "Wrong argument for internal action 'replace': '" + args[i] + "' is not a string");
            }
        }
        String in = ((StringTerm) args[0]).value();
        String out;
        try {
            out = in.replaceAll(((StringTerm) args[1]).value(), ((StringTerm) args[2]).value());
        } catch (RuntimeException e) { // a bad expression, or $2 for a group that is not there
            throw new IaException("unknown", "Error in internal action 'replace': " + e.getMessage().lines().findFirst().orElse(""));
        }
        return un.unifies(args[3], new StringTerm(out));
    }
}
