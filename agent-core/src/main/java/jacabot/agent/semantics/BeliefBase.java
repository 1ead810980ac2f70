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

        Entry(Literal literal) {
            this.literal = literal;
            this.rule = null;
        }

        Entry(Rule rule) {
            this.literal = rule.head();
            this.rule = rule;
        }

        public Literal literal() {
            return literal;
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

    private final LinkedHashMap<Key, ArrayList<Entry>> groups = new LinkedHashMap<>();
    private int size;

    /** {@return the beliefs and rules that may match a literal, in order (a snapshot)} */
    public List<Entry> candidates(Literal l) {
        var g = groups.get(Key.of(l));
        return g == null ? List.of() : new ArrayList<>(g);
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

    public void addRule(Rule rule) {
        groups.computeIfAbsent(Key.of(rule.head()), k -> new ArrayList<>()).add(new Entry(rule));
        size++;
    }

    /**
     * Adds a ground belief. {@return the literal to announce in a {@code +b} event, or null when
     * nothing changed (the belief was there with all these annotations)}
     */
    public Literal add(Literal l, boolean atEnd) {
        var group = groups.computeIfAbsent(Key.of(l), k -> new ArrayList<>());
        for (Entry e : group) {
            if (e.rule == null && e.literal.args().equals(l.args())) {
                if (e.literal.annots().containsAll(l.annots())) {
                    return null;
                }
                e.literal = e.literal.addAnnots(l.annots());
                return l;
            }
        }
        if (atEnd) {
            group.add(new Entry(l));
        } else {
            group.add(0, new Entry(l));
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
        for (int i = 0; i < group.size(); i++) {
            Entry e = group.get(i);
            if (e.rule == null && e.literal.equals(stored)) {
                var left = new ArrayList<Term>(stored.annots());
                left.removeAll(removal.annots());
                boolean hasSource = left.stream().anyMatch(a -> a instanceof Literal al && al.functor().equals("source"));
                if (!hasSource) {
                    group.remove(i);
                    size--;
                    if (group.isEmpty()) {
                        groups.remove(Key.of(stored));
                    }
                    return stored;
                }
                e.literal = stored.withAnnots(left);
                return removal;
            }
        }
        return null;
    }

    /** Removes a stored entry (belief or rule) entirely. */
    public boolean removeEntry(Literal stored) {
        var group = groups.get(Key.of(stored));
        if (group == null) {
            return false;
        }
        for (int i = 0; i < group.size(); i++) {
            if (group.get(i).literal.equals(stored)) {
                group.remove(i);
                size--;
                if (group.isEmpty()) {
                    groups.remove(Key.of(stored));
                }
                return true;
            }
        }
        return false;
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
