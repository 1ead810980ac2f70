package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/**
 * {@code .type(X, T)}: T is {@code number}, {@code string}, {@code list}, {@code atom},
 * {@code literal} (structures, plans, bodies) or {@code free}, as Jason 3.2.0 answers.
 */
final class Type extends DefaultInternalAction {
    Type() {
        super(".type", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[1], Literal.atom(typeOf(args[0])));
    }

    static String typeOf(Term t) {
        if (t instanceof NumberTerm || t instanceof ArithExpr || t instanceof ArithFunction) {
            return "number";
        }
        if (t instanceof StringTerm) {
            return "string";
        }
        if (t instanceof ListTerm) {
            return "list";
        }
        if (t instanceof Var) {
            return "free";
        }
        if (t instanceof Literal l && l.isAtom()) {
            return "atom";
        }
        return "literal";
    }
}
