package jacabot.agent.stdlib;

import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Collection;
import java.util.Map;
import java.util.Queue;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The mutable collections of Jason's {@code .set.*}, {@code .queue.*} and {@code .map.*} actions,
 * carried as object terms: a set is a {@link TermSet} in the standard order of terms, a map a
 * {@link TermMap} with its keys in that order, a priority queue a {@code PriorityBlockingQueue} in
 * that order (as Jason's, so equal priorities come out in the same order), a plain queue an
 * {@code ArrayDeque}. Sets and maps print as Jason's do ({@code {a,b}}, {@code {k->v}}), queues as
 * Java's collections ({@code [a, b]}), which Jason shows too.
 */
final class TermCollections {
    private TermCollections() {
    }

    /** A set of terms in the standard order, printed as Jason prints its sets. */
    static final class TermSet extends TreeSet<Term> {
        private static final long serialVersionUID = 1L;

        TermSet() {
        }

        TermSet(Collection<Term> items) {
            super(items);
        }

        @Override
        public String toString() {
            var sb = new StringBuilder("{");
            for (Term t : this) {
                sb.append(sb.length() > 1 ? "," : "").append(t);
            }
            return sb.append('}').toString();
        }
    }

    /**
     * A map from terms to terms, its keys in the standard order, printed as Jason prints its maps.
     * Two maps are equal (for {@code ==} and unification) only when they are the same map, as in
     * Jason, where sets compare by contents but maps do not.
     */
    static final class TermMap extends TreeMap<Term, Term> {
        private static final long serialVersionUID = 1L;

        TermMap() {
        }

        TermMap(Map<Term, Term> entries) {
            super(entries);
        }

        @Override
        public String toString() {
            var sb = new StringBuilder("{");
            for (var e : entrySet()) {
                sb.append(sb.length() > 1 ? "," : "").append(e.getKey()).append("->").append(e.getValue());
            }
            return sb.append('}').toString();
        }

        @Override
        public boolean equals(Object o) {
            return this == o;
        }

        @Override
        public int hashCode() {
            return System.identityHashCode(this);
        }
    }

    /** {@return the set in t, a new one bound to t when it is a free variable} */
    static TermSet set(String action, Term t, Unifier un) throws IaException {
        return t instanceof Var ? bindNew(t, un, new TermSet()) : set(action, t);
    }

    /** {@return the set in t} */
    static TermSet set(String action, Term t) throws IaException {
        return held(action, t, TermSet.class, "set");
    }

    /** {@return the map in t, a new one bound to t when it is a free variable (as Jason's .map.put)} */
    static TermMap map(String action, Term t, Unifier un) throws IaException {
        return t instanceof Var ? bindNew(t, un, new TermMap()) : map(action, t);
    }

    /** {@return the map in t} */
    static TermMap map(String action, Term t) throws IaException {
        return held(action, t, TermMap.class, "map");
    }

    /** {@return the queue in t} */
    @SuppressWarnings("unchecked")
    static Queue<Term> queue(String action, Term t) throws IaException {
        return held(action, t, Queue.class, "queue");
    }

    private static <C> C bindNew(Term var, Unifier un, C fresh) {
        un.unifies(var, new ObjectTerm(fresh));
        return fresh;
    }

    /** {@return the collection of this type that t holds} */
    private static <C> C held(String action, Term t, Class<C> type, String what) throws IaException {
        if (t instanceof ObjectTerm o && type.isInstance(o.value())) {
            return type.cast(o.value());
        }
        throw IaException.wrongArguments(action, "'" + t + "' is not a " + what);
    }

    /** {@return the elements of a list, set or queue term, or null} */
    static Collection<Term> elements(Term t) {
        if (t instanceof ListTerm l) {
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
