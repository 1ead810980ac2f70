package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;

/**
 * The belief base: beliefs and rules grouped by predicate (functor, arity, negation), each group
 * in order. {@code +b} adds at the beginning of its group, {@code +>b} and initial beliefs at the
 * end; adding a belief that exists merges its annotations in place.
 */
public final class BeliefBase {
    /** A stored belief or rule. */
    public static final class Entry {
        private Literal literal;
        private final Rule rule;
        private final boolean ground;

        Entry(Literal literal) {
            this.literal = literal;
            this.rule = null;
            this.ground = literal.isGround();
        }

        Entry(Rule rule) {
            this.literal = rule.head();
            this.rule = rule;
            this.ground = false;
        }

        public Literal literal() {
            return literal;
        }

        /** {@return whether the fact has no variables (annotations included)} */
        public boolean isGround() {
            return ground;
        }

        /** {@return the rule, or null for a fact} */
        public Rule rule() {
            return rule;
        }
    }

    /**
     * A predicate: functor, arity and negation (equality written out: it is looked up for every
     * belief change). Lookups use one mutable probe instead of a new key each time.
     */
    private static final class Key {
        private String functor;
        private int arity;
        private boolean negated;

        private Key(String functor, int arity, boolean negated) {
            this.functor = functor;
            this.arity = arity;
            this.negated = negated;
        }

        Key set(Literal l) {
            functor = l.functor();
            arity = l.arity();
            negated = l.negated();
            return this;
        }

        static Key of(Literal l) {
            return new Key(l.functor(), l.arity(), l.negated());
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.arity == arity && k.negated == negated && k.functor.equals(functor);
        }

        @Override
        public int hashCode() {
            return functor.hashCode() * 31 + arity * 2 + (negated ? 1 : 0);
        }
    }

    /**
     * The entries of one predicate in order, in a deque since {@code +b} adds at the front, with a
     * snapshot reused by queries until the group changes.
     */
    private static final class Group {
        /** Its key in the map (kept with a spare group: the same predicate often comes back). */
        private Key key;
        private final ArrayDeque<Entry> entries = new ArrayDeque<>();
        private List<Entry> snapshot;
        /** The facts by their arguments: adding a known fact must not scan a large group. */
        private final HashMap<List<Term>, Entry> facts = new HashMap<>();

        List<Entry> snapshot() {
            if (snapshot == null) {
                snapshot = List.copyOf(entries);
            }
            return snapshot;
        }

        void add(Entry e, boolean atEnd) {
            snapshot = null;
            if (atEnd) {
                entries.addLast(e);
            } else {
                entries.addFirst(e);
            }
        }

        void remove(Entry e) {
            snapshot = null;
            entries.removeFirstOccurrence(e);
            if (e.rule == null) {
                facts.remove(e.literal.args());
            }
        }
    }

    private final LinkedHashMap<Key, Group> groups = new LinkedHashMap<>();
    /** The last group emptied, reused for the next new predicate (a belief added and removed in a loop). */
    private Group spare;
    private int size;

    /** The lookup key; the belief base is used by its agent's thread only. */
    private final Key probe = new Key(null, 0, false);

    private Group group(Literal l) {
        return groups.get(probe.set(l));
    }

    private Group groupFor(Literal l) {
        Group g = group(l);
        if (g == null) {
            g = spare == null ? new Group() : spare;
            spare = null;
            if (g.key == null || !g.key.equals(probe)) {
                g.key = Key.of(l);
            }
            groups.put(g.key, g);
        }
        return g;
    }

    /**
     * {@return the beliefs and rules that may match a literal, in order} It is a snapshot: queries
     * iterate it while plans change the belief base.
     */
    public List<Entry> candidates(Literal l) {
        var g = group(l);
        return g == null ? List.of() : g.snapshot();
    }

    /** {@return the stored fact with exactly these arguments (any annotations), or null} */
    public Literal fact(Literal l) {
        var g = group(l);
        if (g == null) {
            return null;
        }
        Entry e = g.facts.get(l.args());
        return e == null ? null : e.literal;
    }

    /** {@return every stored entry, group by group} */
    public List<Entry> all() {
        var out = new ArrayList<Entry>();
        groups.values().forEach(g -> out.addAll(g.entries));
        return out;
    }

    public int size() {
        return size;
    }

    public void addRule(Rule rule, boolean atEnd) {
        groupFor(rule.head()).add(new Entry(rule), atEnd);
        size++;
    }

    /**
     * Adds a ground belief. {@return the literal to announce in a {@code +b} event, or null when
     * nothing changed (the belief was there with all these annotations)}
     */
    public Literal add(Literal l, boolean atEnd) {
        var group = groupFor(l);
        Entry known = group.facts.get(l.args());
        if (known != null) {
            if (containsAll(known.literal.annots(), l.annots())) {
                return null;
            }
            // the event announces only the new annotations, as Jason does
            var fresh = new ArrayList<Term>(l.annots());
            fresh.removeAll(known.literal.annots());
            known.literal = known.literal.addAnnots(l.annots());
            return l.withAnnots(fresh);
        }
        Entry e = new Entry(l);
        group.facts.put(l.args(), e);
        group.add(e, atEnd);
        size++;
        return l;
    }

    /**
     * Removes from the stored belief {@code stored} the annotations of {@code removal}; the belief
     * disappears when no {@code source} annotation is left. {@return the removed part, or null}
     */
    public Literal remove(Literal stored, Literal removal) {
        var group = group(stored);
        if (group == null) {
            return null;
        }
        Entry e = group.facts.get(stored.args());
        if (e == null || (e.literal != stored && !e.literal.equals(stored))) {
            return null;
        }
        return removeAnnots(group, e, removal);
    }

    /**
     * As {@link #remove} for the stored fact with the arguments of a ground literal, when it has
     * all the literal's annotations (one lookup for the usual {@code -b(1)}). {@return the removed
     * part, or null when there is no such fact}
     */
    public Literal removeFact(Literal removal) {
        var group = group(removal);
        if (group == null) {
            return null;
        }
        Entry e = group.facts.get(removal.args());
        if (e == null || !containsAll(e.literal.annots(), removal.annots())) {
            return null;
        }
        return removeAnnots(group, e, removal);
    }

    private Literal removeAnnots(Group group, Entry e, Literal removal) {
        Literal stored = e.literal;
        if (!keepsSource(stored.annots(), removal.annots())) {
            removeFromGroup(group, e, stored);
            return stored;
        }
        group.snapshot = null;
        var left = new ArrayList<Term>(stored.annots());
        left.removeAll(removal.annots());
        e.literal = stored.withAnnots(left);
        return removal;
    }

    /** {@code all.containsAll(some)} by index, without iterators (annotation lists are short). */
    private static boolean containsAll(List<Term> all, List<Term> some) {
        for (int i = 0, n = some.size(); i < n; i++) {
            if (!all.contains(some.get(i))) {
                return false;
            }
        }
        return true;
    }

    /** {@return whether some source annotation of {@code annots} is not among those removed} */
    private static boolean keepsSource(List<Term> annots, List<Term> removed) {
        for (int i = 0, n = annots.size(); i < n; i++) {
            if (annots.get(i) instanceof Literal a && a.functor().equals("source") && !removed.contains(a)) {
                return true;
            }
        }
        return false;
    }

    /** Removes a stored entry (belief or rule) entirely. */
    public boolean removeEntry(Literal stored) {
        var group = group(stored);
        if (group == null) {
            return false;
        }
        for (Entry e : group.entries) {
            if (e.literal.equals(stored)) {
                removeFromGroup(group, e, stored);
                return true;
            }
        }
        return false;
    }

    private void removeFromGroup(Group group, Entry e, Literal stored) {
        group.remove(e);
        size--;
        if (group.entries.isEmpty()) {
            groups.remove(probe.set(stored));
            spare = group;
        }
    }

    public List<Literal> beliefs() {
        var out = new ArrayList<Literal>();
        for (var g : groups.values()) {
            for (Entry e : g.entries) {
                if (e.rule == null) {
                    out.add(e.literal);
                }
            }
        }
        return Collections.unmodifiableList(out);
    }
}
