package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.Collections;
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

    private record Key(String functor, int arity, boolean negated) {
        static Key of(Literal l) {
            return new Key(l.functor(), l.arity(), l.negated());
        }
    }

    /** The entries of one predicate, with a snapshot reused by queries until the group changes. */
    private static final class Group extends ArrayList<Entry> {
        private static final long serialVersionUID = 1L;
        private transient List<Entry> snapshot;
        /** The facts by their arguments: adding a known fact must not scan a large group. */
        private final transient java.util.HashMap<List<Term>, Entry> facts = new java.util.HashMap<>();

        List<Entry> snapshot() {
            if (snapshot == null) {
                snapshot = List.copyOf(this);
            }
            return snapshot;
        }

        void changed() {
            snapshot = null;
        }
    }

    private final LinkedHashMap<Key, Group> groups = new LinkedHashMap<>();
    private int size;

    /**
     * {@return the beliefs and rules that may match a literal, in order} It is a snapshot: queries
     * iterate it while plans change the belief base.
     */
    public List<Entry> candidates(Literal l) {
        var g = groups.get(Key.of(l));
        return g == null ? List.of() : g.snapshot();
    }

    /** {@return the stored fact with exactly these arguments (any annotations), or null} */
    public Literal fact(Literal l) {
        var g = groups.get(Key.of(l));
        if (g == null) {
            return null;
        }
        Entry e = g.facts.get(l.args());
        return e == null ? null : e.literal;
    }

    /** {@return every stored entry, group by group} */
    public List<Entry> all() {
        var out = new ArrayList<Entry>();
        groups.values().forEach(out::addAll);
        return out;
    }

    public int size() {
        return size;
    }

    public void addRule(Rule rule, boolean atEnd) {
        Group g = groups.computeIfAbsent(Key.of(rule.head()), k -> new Group());
        if (atEnd) {
            g.add(new Entry(rule));
        } else {
            g.add(0, new Entry(rule));
        }
        g.changed();
        size++;
    }

    /**
     * Adds a ground belief. {@return the literal to announce in a {@code +b} event, or null when
     * nothing changed (the belief was there with all these annotations)}
     */
    public Literal add(Literal l, boolean atEnd) {
        var group = groups.computeIfAbsent(Key.of(l), k -> new Group());
        Entry known = group.facts.get(l.args());
        if (known != null) {
            if (known.literal.annots().containsAll(l.annots())) {
                return null;
            }
            // the event announces only the new annotations, as Jason does
            var fresh = new ArrayList<Term>(l.annots());
            fresh.removeAll(known.literal.annots());
            known.literal = known.literal.addAnnots(l.annots());
            return l.withAnnots(fresh);
        }
        group.changed();
        Entry e = new Entry(l);
        group.facts.put(l.args(), e);
        if (atEnd) {
            group.add(e);
        } else {
            group.add(0, e);
        }
        size++;
        return l;
    }

    /**
     * Removes from the stored belief {@code stored} the annotations of {@code removal}; the belief
     * disappears when no {@code source} annotation is left. {@return the removed part, or null}
     */
    public Literal remove(Literal stored, Literal removal) {
        var group = groups.get(Key.of(stored));
        if (group == null) {
            return null;
        }
        Entry e = group.facts.get(stored.args());
        if (e == null || !e.literal.equals(stored)) {
            return null;
        }
        group.changed();
        var left = new ArrayList<Term>(stored.annots());
        left.removeAll(removal.annots());
        boolean hasSource = left.stream().anyMatch(a -> a instanceof Literal al && al.functor().equals("source"));
        if (!hasSource) {
            removeFromGroup(group, e, stored);
            return stored;
        }
        e.literal = stored.withAnnots(left);
        return removal;
    }

    /** Removes a stored entry (belief or rule) entirely. */
    public boolean removeEntry(Literal stored) {
        var group = groups.get(Key.of(stored));
        if (group == null) {
            return false;
        }
        for (int i = 0; i < group.size(); i++) {
            Entry e = group.get(i);
            if (e.literal.equals(stored)) {
                removeFromGroup(group, e, stored);
                return true;
            }
        }
        return false;
    }

    private void removeFromGroup(Group group, Entry e, Literal stored) {
        group.changed();
        group.remove(e);
        if (e.rule == null) {
            group.facts.remove(e.literal.args());
        }
        size--;
        if (group.isEmpty()) {
            groups.remove(Key.of(stored));
        }
    }

    public List<Literal> beliefs() {
        var out = new ArrayList<Literal>();
        for (var g : groups.values()) {
            for (Entry e : g) {
                if (e.rule == null) {
                    out.add(e.literal);
                }
            }
        }
        return Collections.unmodifiableList(out);
    }
}
