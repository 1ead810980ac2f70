package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/**
 * {@code .copy_term(T, C)} and {@code .rename_apart(T, C)}: C is T with its free variables
 * renamed to fresh ones (the same variable twice stays one variable). As Jason's, a T that is a
 * free variable itself is not renamed: C then shares it. A number or a string (no literal) fails
 * with {@code error(unknown)}, as in Jason.
 */
final class CopyTerm extends DefaultInternalAction {
    private CopyTerm(String name) {
        super(name, 2, 2);
    }

    static CopyTerm copyTerm() {
        return new CopyTerm(".copy_term");
    }

    static CopyTerm renameApart() {
        return new CopyTerm(".rename_apart");
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term t = args[0];
        if (t instanceof Var || t instanceof AnnotatedVar) {
            return un.unifies(args[1], t);
        }
        if (t instanceof NumberTerm || t instanceof StringTerm) {
            throw new IaException("unknown", "Wrong argument for internal action '" + name().substring(1) + "': '" + t + "' is not a literal");
        }
        return un.unifies(args[1], Renamer.renameApart(t, ag));
    }
}
