package jacabot.app.inspector;

import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.IdentityHashMap;
import java.util.List;

/**
 * The beliefs section of a {@link MindState}, printed only where the belief base changed. When
 * the belief base has had no change since the last capture, the last list is the answer; else
 * only the predicates (groups) whose change count moved are read again, the others give the
 * beliefs they gave. Facts and rules are immutable: within a changed group, one the last capture
 * showed is shown as the same object (its text kept). A fact or rule holding an object term that
 * is not a value (its Java object may change) is printed at every capture, and so is its group.
 * The list is a {@link BeliefList} of the groups' arrays: an unchanged group's array is shared
 * with the last capture's list, not copied belief by belief. Not thread-safe: the agent's thread
 * captures.
 */
final class BeliefTexts {
    /**
     * One group as the last capture showed it: each entry's fact or rule (null for one printed at
     * every capture), and its belief.
     */
    private record Shown(long changedAt, Object[] entries, MindState.Belief[] beliefs, boolean stable,
            IdentityHashMap<Object, MindState.Belief> index) {
        /** Groups up to this size are searched entry by entry, larger ones through an index. */
        static final int SCAN = 16;

        Shown(long changedAt, Object[] entries, MindState.Belief[] beliefs, boolean stable) {
            this(changedAt, entries, beliefs, stable, entries.length <= SCAN ? null : new IdentityHashMap<>());
            if (index != null) {
                for (int i = 0; i < entries.length; i++) {
                    if (entries[i] != null) {
                        index.put(entries[i], beliefs[i]);
                    }
                }
            }
        }

        /** {@return the belief shown for this fact or rule, or null} */
        MindState.Belief find(Object entry) {
            if (index != null) {
                return index.get(entry);
            }
            for (int i = 0; i < entries.length; i++) {
                if (entries[i] == entry) {
                    return beliefs[i];
                }
            }
            return null;
        }
    }

    /** Annotation texts kept at most; past this the memory starts anew. */
    static final int ANNOTS_KEPT = 4096;
    /** The texts of the annotations (and sources) of facts shown, by term object. */
    private final IdentityHashMap<Term, String> annotTexts = new IdentityHashMap<>();
    /** The belief base's change count at the last capture. */
    private long changes = -1;
    private List<MindState.Belief> last = BeliefList.EMPTY;
    /** Whether some group of the last list holds an entry printed anew at every capture. */
    private boolean holdsObjects;
    /**
     * The last capture's groups in order, and how each was shown. A capture finds a group where the
     * last one had it, or a little further on (a changed property's group moves to the end): an
     * array read, not a hash lookup, for each of the base's predicates.
     */
    private Object[] groups = new Object[0];
    private Shown[] shown = new Shown[0];
    private int count;

    /** {@return the beliefs and rules, in the belief base's order} */
    List<MindState.Belief> of(BeliefBase base) {
        if (base.changes() == changes && !holdsObjects) {
            return last;
        }
        var walk = new Walk(Math.max(count + 4, 16));
        base.forEachGroup((group, changedAt, entries) -> {
            Shown was = walk.find(group);
            Shown s = was != null && was.changedAt() == changedAt && was.stable() ? was : show(changedAt, entries, was);
            walk.add(group, s);
            walk.objects |= !s.stable();
        });
        groups = walk.groups;
        shown = walk.shown;
        count = walk.count;
        changes = base.changes();
        holdsObjects = walk.objects;
        var parts = new MindState.Belief[count][];
        for (int k = 0; k < count; k++) {
            parts[k] = shown[k].beliefs(); // a group not shown anew: its array of the last capture
        }
        last = new BeliefList(parts, count);
        return last;
    }

    /** One capture's walk of the groups: where it is in the last capture's, and what it has seen. */
    private final class Walk {
        Object[] groups;
        Shown[] shown;
        int count;
        boolean objects;
        /** The last capture's group expected next. */
        private int next;

        Walk(int capacity) {
            groups = new Object[capacity];
            shown = new Shown[capacity];
        }

        /** {@return how the last capture showed {@code group}, or null} */
        Shown find(Object group) {
            int k = BeliefList.indexFrom(BeliefTexts.this.groups, BeliefTexts.this.count, group, next);
            if (k < 0) {
                return null;
            }
            if (k >= next) {
                next = k + 1; // found in place or further on: the walk goes on from there
            }
            return BeliefTexts.this.shown[k];
        }

        void add(Object group, Shown s) {
            if (count == groups.length) {
                groups = Arrays.copyOf(groups, count * 2);
                shown = Arrays.copyOf(shown, count * 2);
            }
            groups[count] = group;
            shown[count] = s;
            count++;
        }
    }

    /** {@return a group's entries as beliefs, those {@code was} showed (if any) as the same objects} */
    private Shown show(long changedAt, Collection<BeliefBase.Entry> entries, Shown was) {
        var keys = new Object[entries.size()];
        var beliefs = new MindState.Belief[entries.size()];
        boolean stable = true;
        int k = 0;
        for (BeliefBase.Entry e : entries) {
            Object key = e.rule() != null ? e.rule() : e.literal();
            MindState.Belief b = was == null ? null : was.find(key);
            if (b == null) {
                b = e.rule() != null ? rule(e.rule()) : belief(e.literal(), annotTexts);
                if (e.rule() != null ? !StableText.of(e.rule().head()) || !StableText.of(e.rule().body())
                        : !StableText.of(e.literal())) {
                    stable = false;
                    key = null; // never found again: printed anew at the next capture
                }
            }
            keys[k] = key;
            beliefs[k] = b;
            k++;
        }
        return new Shown(changedAt, keys, beliefs, stable);
    }

    private static MindState.Belief rule(Rule r) {
        return new MindState.Belief(r.toString(), List.of(), List.of());
    }

    /** {@return a fact as the inspector shows it: its literal, its sources, its other annotations} */
    static MindState.Belief belief(Literal l) {
        return belief(l, null);
    }

    /**
     * As {@link #belief(Literal)}, each annotation's text taken from {@code texts} (by term object)
     * when it is there, and kept there when its term is stable: a property's new value carries
     * its artifact's annotation terms, the same objects at every step.
     */
    private static MindState.Belief belief(Literal l, IdentityHashMap<Term, String> texts) {
        var sources = new ArrayList<String>();
        var annots = new ArrayList<String>();
        for (Term a : l.annots()) {
            if (a instanceof Literal s && s.functor().equals("source") && s.arity() == 1) {
                sources.add(text(s.arg(0), texts));
            } else {
                annots.add(text(a, texts));
            }
        }
        return new MindState.Belief(l.withoutAnnots().toString(), sources, annots);
    }

    private static String text(Term t, IdentityHashMap<Term, String> texts) {
        if (texts == null) {
            return t.toString();
        }
        String s = texts.get(t);
        if (s == null) {
            s = t.toString();
            if (StableText.of(t)) {
                if (texts.size() >= ANNOTS_KEPT) {
                    texts.clear();
                }
                texts.put(t, s);
            }
        }
        return s;
    }
}
