package jacabot.agent.stdlib;

import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collection;
import java.util.Iterator;
import java.util.NoSuchElementException;

/**
 * The solutions of an action that backtracks over candidates ({@code .member}, {@code .map.key}):
 * a term unified with each candidate in turn, a solution's unifier made only when it is asked for
 * (a plan body takes the first only). The candidates and the bindings are those of the call: a
 * {@code for} loop's body may change both before it asks for the next.
 */
final class EachUnifying implements Iterator<Unifier> {
    private final Unifier base;
    private final Term x;
    private final Term[] candidates;
    private int i;
    private Unifier next;

    EachUnifying(Unifier un, Term x, Collection<Term> candidates) {
        this.base = un.copy();
        this.x = x;
        this.candidates = candidates.toArray(new Term[0]);
    }

    @Override
    public boolean hasNext() {
        while (next == null && i < candidates.length) {
            next = base.unifiedCopy(x, candidates[i++]);
        }
        return next != null;
    }

    @Override
    public Unifier next() {
        if (!hasNext()) {
            throw new NoSuchElementException();
        }
        Unifier n = next;
        next = null;
        return n;
    }
}
