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
import java.util.ArrayList;

/**
 * {@code .type(X, T)}: T is {@code number}, {@code string}, {@code list}, {@code atom},
 * {@code literal} (structures, plans, bodies) or {@code free}, as Jason 3.2.0 answers first;
 * then {@code literal} for an atom and {@code ground} for a ground term.
 */
final class Type extends DefaultInternalAction {
    Type() {
        super(".type", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        // the first answer is the most specific; an atom is also a literal, a ground term is ground
        var answers = new ArrayList<String>();
        answers.add(typeOf(args[0]));
        if (answers.get(0).equals("atom")) {
            answers.add("literal");
        }
        if (args[0].isGround()) {
            answers.add("ground");
        }
        var out = new ArrayList<Unifier>();
        for (String a : answers) {
            Unifier c = un.copy();
            if (c.unifies(args[1], Literal.atom(a))) {
                out.add(c);
            }
        }
        return out.iterator();
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
