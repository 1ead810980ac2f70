package jacabot.agent.semantics;

import jacabot.agent.semantics.BeliefBase.Entry;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/**
 * The annotations of a stored belief when the same belief is added again (the new ones merge in,
 * kept in the standard order) or removed in part (the belief goes with its last source), as
 * Jason's belief base keeps them.
 */
final class BeliefAnnotations {
    private BeliefAnnotations() {
    }

    /**
     * Adds the annotations of {@code l} to a stored belief. {@return the literal with only the new
     * annotations, which the event announces as Jason does, or null when there is none} Each new
     * one is inserted in the sorted annotations: a belief told by a thousand agents has a thousand
     * sources, and merging them all again at every message was quadratic in the number of senders.
     */
    static Literal merge(Entry known, Literal l) {
        Literal merged = known.literal();
        List<Term> more = l.annots();
        List<Term> fresh = null;
        for (int i = 0, n = more.size(); i < n; i++) {
            Term a = more.get(i);
            int at = find(merged.annots(), a);
            if (at >= 0) {
                continue;
            }
            if (at == UNORDERED) {
                return mergeAll(known, l);
            }
            merged = merged.addAnnot(a);
            if (fresh == null) {
                fresh = new ArrayList<>(n - i);
            }
            fresh.add(a);
        }
        if (fresh == null) {
            return null;
        }
        known.setLiteral(merged);
        return fresh.size() == more.size() ? l : l.withAnnots(fresh);
    }

    /** As {@link #merge}, by sorting all annotations again (terms the order does not tell apart). */
    private static Literal mergeAll(Entry known, Literal l) {
        var fresh = new ArrayList<Term>(l.annots());
        fresh.removeAll(known.literal().annots());
        if (fresh.isEmpty()) {
            return null;
        }
        known.setLiteral(known.literal().addAnnots(l.annots()));
        return l.withAnnots(fresh);
    }

    /** A term of the standard order's rank that equals none of the terms it ranks equal to. */
    private static final int UNORDERED = Integer.MIN_VALUE;

    /**
     * {@return the position of {@code t} in sorted annotations, a negative number when it is not
     * there, or {@link #UNORDERED} when another term takes its place in the order}
     */
    private static int find(List<Term> sorted, Term t) {
        int lo = 0;
        int hi = sorted.size() - 1;
        while (lo <= hi) {
            int mid = (lo + hi) >>> 1;
            int c = sorted.get(mid).compareTo(t);
            if (c < 0) {
                lo = mid + 1;
            } else if (c > 0) {
                hi = mid - 1;
            } else {
                return sorted.get(mid).equals(t) ? mid : UNORDERED;
            }
        }
        return -1;
    }

    /** {@code all.containsAll(some)} by index, without iterators (annotation lists are short). */
    static boolean containsAll(List<Term> all, List<Term> some) {
        for (int i = 0, n = some.size(); i < n; i++) {
            if (!all.contains(some.get(i))) {
                return false;
            }
        }
        return true;
    }

    /** {@return whether some source annotation of {@code annots} is not among those removed} */
    static boolean keepsSource(List<Term> annots, List<Term> removed) {
        for (int i = 0, n = annots.size(); i < n; i++) {
            if (annots.get(i) instanceof Literal a && a.functor().equals("source") && !removed.contains(a)) {
                return true;
            }
        }
        return false;
    }
}
