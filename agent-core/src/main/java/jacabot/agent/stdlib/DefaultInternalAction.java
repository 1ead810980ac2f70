package jacabot.agent.stdlib;

import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.InternalAction;
import jacabot.agent.semantics.Unifier;
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
