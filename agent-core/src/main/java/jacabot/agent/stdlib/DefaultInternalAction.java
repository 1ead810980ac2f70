package jacabot.agent.stdlib;

import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.InternalAction;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Var;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.util.Collections;
import java.util.Iterator;
import java.util.List;

/** Base of the standard internal actions: arity bounds and argument helpers. */
abstract class DefaultInternalAction implements InternalAction {
    private final String name;
    private final int min;
    private final int max;

    DefaultInternalAction(String name, int min, int max) {
        this.name = name;
        this.min = min;
        this.max = max;
    }

    String name() {
        return name;
    }

    @Override
    public int minArgs() {
        return min;
    }

    @Override
    public int maxArgs() {
        return max;
    }

    double number(Term t) throws IaException {
        if (t instanceof NumberTerm n) {
            return n.value();
        }
        throw IaException.wrongArguments(name, "'" + t + "' is not a number");
    }

    ListTerm list(Term t) throws IaException {
        if (t instanceof ListTerm l) {
            return l;
        }
        throw IaException.wrongArguments(name, "'" + t + "' is not a list");
    }

    /** Jason's checks of {@code .union}, {@code .intersection} and {@code .difference}, in its words. */
    void checkListOperands(Term[] args) throws IaException {
        if (!(args[0] instanceof ListTerm)) {
            throw IaException.wrongArguments(name, "first argument '" + args[0] + "'is not a list.");
        }
        if (!(args[1] instanceof ListTerm)) {
            throw IaException.wrongArguments(name, "second argument '" + args[1] + "'is not a list.");
        }
        if (!(args[2] instanceof Var) && !(args[2] instanceof ListTerm)) {
            throw IaException.wrongArguments(name, "last argument '" + args[2] + "'is not a list nor a variable.");
        }
    }

    /** The first argument a list, in Jason's words ({@code .sort}, {@code .min}, {@code .max}). */
    void checkFirstIsList(Term[] args) throws IaException {
        if (!(args[0] instanceof ListTerm)) {
            throw IaException.wrongArguments(name, "first argument must be a list");
        }
    }

    /** The first argument a literal, in Jason's words ({@code .succeed_goal}, {@code .fail_goal}, {@code .resume}). */
    Literal firstLiteral(Term[] args) throws IaException {
        if (args[0] instanceof Literal l) {
            return l;
        }
        throw IaException.wrongArguments(name, "first argument must be a literal");
    }

    Literal literal(Term t) throws IaException {
        if (t instanceof Literal l) {
            return l;
        }
        throw IaException.wrongArguments(name, "'" + t + "' is not a literal");
    }

    /** Strings print without quotes, other terms in AgentSpeak syntax. */
    static String text(Term t) {
        if (t instanceof StringTerm s) {
            return s.value();
        }
        // an atom prints as its functor: no text to build (.send's receiver and performative)
        return t instanceof Literal l && l.isAtom() && l.ns() == null ? l.functor() : t.toString();
    }

    static Iterator<Unifier> none() {
        return Collections.emptyIterator();
    }

    static Object unifyResult(Unifier un, Term var, Term value) {
        return un.unifies(var, value);
    }

    static ListTerm listOf(List<? extends Term> items) {
        return ListTerm.of(items);
    }
}
