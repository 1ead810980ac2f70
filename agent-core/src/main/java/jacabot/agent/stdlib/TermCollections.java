package jacabot.agent.stdlib;

import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Collection;
import java.util.TreeSet;

/**
 * The mutable collections of Jason's {@code .set.*} and {@code .queue.*} actions, carried as
 * object terms: a set is a {@code TreeSet} in the standard order of terms, a priority queue a
 * {@code PriorityBlockingQueue} in that order (as Jason's, so equal priorities come out in the
 * same order), a plain queue an {@code ArrayDeque}.
 */
final class TermCollections {
    private TermCollections() {
    }

    /** {@return the set in t, a new one bound to t when it is a free variable} */
    @SuppressWarnings("unchecked")
    static TreeSet<Term> set(String action, Term t, Unifier un) throws IaException {
        if (t instanceof Var) {
            var s = new TreeSet<Term>();
            un.unifies(t, new ObjectTerm(s));
            return s;
        }
        if (t instanceof ObjectTerm o && o.value() instanceof TreeSet<?> s) {
            return (TreeSet<Term>) s;
        }
        throw IaException.wrongArguments(action, "'" + t + "' is not a set");
    }

    /** {@return the queue in t} */
    @SuppressWarnings("unchecked")
    static java.util.Queue<Term> queue(String action, Term t) throws IaException {
        if (t instanceof ObjectTerm o && o.value() instanceof java.util.Queue<?> q) {
            return (java.util.Queue<Term>) q;
        }
        throw IaException.wrongArguments(action, "'" + t + "' is not a queue");
    }

    /** {@return the elements of a list, set or queue term, or null} */
    static Collection<Term> elements(Term t) {
        if (t instanceof jacabot.agent.syntax.ListTerm l) {
            return l.elements();
        }
        if (t instanceof ObjectTerm o && o.value() instanceof Collection<?> c) {
            @SuppressWarnings("unchecked")
            Collection<Term> terms = (Collection<Term>) c;
            return terms;
        }
        return null;
    }
}
