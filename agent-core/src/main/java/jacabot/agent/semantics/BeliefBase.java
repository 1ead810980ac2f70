package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
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
        /** The hash of a fact's arguments, kept by its group's {@link FactIndex}. */
        int argsHash;

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

        void setLiteral(Literal l) {
            literal = l;
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

        /** The rule's distinct variables, head first, in order of first occurrence (computed once). */
        private Var[] ruleVars;

        Var[] ruleVars() {
            if (ruleVars == null) {
                var vars = new LinkedHashSet<Var>();
                rule.head().collectVars(vars::add);
                rule.body().collectVars(vars::add);
                ruleVars = vars.toArray(new Var[0]);
            }
            return ruleVars;
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
        /** The namespace: null for the default one. */
        private Term ns;

        private Key(String functor, int arity, boolean negated, Term ns) {
            this.functor = functor;
            this.arity = arity;
            this.negated = negated;
            this.ns = ns;
        }

        Key set(Literal l) {
            functor = l.functor();
            arity = l.arity();
            negated = l.negated();
            ns = l.ns();
            return this;
        }

        static Key of(Literal l) {
            return new Key(l.functor(), l.arity(), l.negated(), l.ns());
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.arity == arity && k.negated == negated && k.functor.equals(functor)
                    && (k.ns == ns || k.ns != null && k.ns.equals(ns));
        }

        @Override
        public int hashCode() {
            int h = functor.hashCode() * 31 + arity * 2 + (negated ? 1 : 0);
            return ns == null ? h : h * 31 + ns.hashCode();
        }
    }

    /**
     * The entries of one predicate in order, in a deque since {@code +b} adds at the front, with a
     * snapshot reused by queries until the group changes, and an index by first argument built
     * once a large group is queried often enough unchanged.
     */
    private static final class Group {
        /** Groups smaller than this are scanned, not indexed. */
        private static final int INDEX_FROM = 16;
        /** Queries of an unchanged group before its index is built (a changing group is scanned). */
        private static final int INDEX_AFTER = 4;
        /** Entries whose first argument is not a constant (rules with a variable there): at most this many. */
        private static final int MAX_UNKEYED = 8;

        /** Its key in the map (kept with a spare group: the same predicate often comes back). */
        private Key key;
        private final ArrayDeque<Entry> entries = new ArrayDeque<>();
        private final Collection<Entry> readOnly = Collections.unmodifiableCollection(entries);
        /** The belief base's change count at this group's last change: no two states of a group share one. */
        private long changedAt;
        private List<Entry> snapshot;
        /** The facts by their arguments: adding a known fact must not scan a large group. */
        private final FactIndex facts = new FactIndex();

        Entry fact(List<Term> args) {
            return facts.get(args);
        }

        /** The entries by first argument, each list with the unkeyed entries in their places. */
        private HashMap<Object, List<Entry>> byFirst;
        /** The entries whose first argument is not a constant, in order. */
        private List<Entry> unkeyed;
        private int queriesUnchanged;

        List<Entry> snapshot() {
            if (snapshot == null) {
                // a group of one (a counter, a state) without the array List.copyOf makes
                snapshot = entries.size() == 1 ? List.of(entries.peekFirst()) : List.copyOf(entries);
                byFirst = null;
                queriesUnchanged = 0;
            }
            return snapshot;
        }

        /** {@return the entries that may match a query whose first argument is the constant {@code key}} */
        List<Entry> candidates(Object key) {
            List<Entry> all = snapshot();
            if (byFirst == null) {
                if (all.size() < INDEX_FROM || ++queriesUnchanged < INDEX_AFTER || !index(all)) {
                    return all;
                }
            }
            List<Entry> some = byFirst.get(key);
            return some != null ? some : unkeyed;
        }

        /** Builds the index of {@code all}. {@return false when too many entries are unkeyed} */
        private boolean index(List<Entry> all) {
            var map = new HashMap<Object, List<Entry>>();
            var loose = new ArrayList<Entry>();
            for (Entry e : all) {
                Object k = key(e.literal.arg(0), null);
                if (k == null) {
                    if (loose.size() == MAX_UNKEYED) {
                        queriesUnchanged = Integer.MIN_VALUE;
                        return false;
                    }
                    loose.add(e);
                    map.values().forEach(l -> l.add(e));
                } else {
                    map.computeIfAbsent(k, x -> new ArrayList<>(loose)).add(e);
                }
            }
            byFirst = map;
            unkeyed = loose;
            return true;
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
                facts.remove(e);
            }
        }
    }

    private final LinkedHashMap<Key, Group> groups = new LinkedHashMap<>();
    /**
     * The namespaces the belief base has had, in order of arrival: the default one, and
     * {@code kqml}, which every Jason agent has for the rules of its message plans.
     */
    private final LinkedHashSet<Term> knownNs = new LinkedHashSet<>(
            List.of(Literal.DEFAULT_NS, Literal.atom("kqml")));
    /** The last group emptied, reused for the next new predicate (a belief added and removed in a loop). */
    private Group spare;
    /** The group last put in the map: the last in its order while it is there. */
    private Group newest;
    /**
     * The newest group, emptied but left in the map (where an empty group changes nothing), so
     * that a belief added and removed in a loop does not take its group out and put it back each
     * turn; it leaves once another group comes (it would not be the last any more).
     */
    private Group parked;
    private int size;
    /** Changes made so far (an entry added, removed or given other annotations): see {@link #changes()}. */
    private long changes;

    private void changed(Group g) {
        g.changedAt = ++changes;
    }

    /** The lookup key; the belief base is used by its agent's thread only. */
    private final Key probe = new Key(null, 0, false, null);

    private Group group(Literal l) {
        return groups.get(probe.set(l));
    }

    private Group groupFor(Literal l) {
        Group g = group(l);
        if (g == parked) {
            parked = null;
        }
        if (g == null) {
            if (parked != null) {
                groups.remove(parked.key);
                spare = parked;
                parked = null;
                probe.set(l);
            }
            if (l.ns() != null) {
                knownNs.add(l.ns()); // the default namespace is there from the start
            }
            g = spare == null ? new Group() : spare;
            spare = null;
            if (g.key == null || !g.key.equals(probe)) {
                g.key = Key.of(l);
            }
            groups.put(g.key, g);
            newest = g;
        }
        return g;
    }

    /**
     * {@return the beliefs and rules that may match a literal, in order} It is a snapshot: queries
     * iterate it while plans change the belief base.
     */
    public List<Entry> candidates(Literal l) {
        return candidates(l, l.arity() == 0 ? null : l.arg(0));
    }

    /** As {@link #candidates(Literal)}, for a query whose first argument is {@code first} (its value when a bound variable) */
    List<Entry> candidates(Literal l, Term first) {
        return candidates(l, l.ns(), first);
    }

    /**
     * As {@link #candidates(Literal, Term)}, in namespace {@code ns} (the query's own, or its value):
     * a variable namespace ({@code N::b}) asks every namespace, in the order the groups came.
     */
    List<Entry> candidates(Literal l, Term ns, Term first) {
        if (ns instanceof Var) {
            var out = new ArrayList<Entry>();
            for (Term n : namespaces()) {
                var g = group(l.withNs(n));
                if (g != null) {
                    out.addAll(g.snapshot());
                }
            }
            return out;
        }
        if (ns != l.ns()) {
            l = l.withNs(ns);
        }
        var g = group(l);
        if (g == null) {
            return List.of();
        }
        Object key = first == null ? null : key(first, numberProbe);
        return key == null ? g.snapshot() : g.candidates(key);
    }

    /**
     * {@return the entries of the literal's predicate as they are, not a snapshot} For a caller
     * that stops iterating before it changes the belief base ({@code -b(X)} removes the first
     * match): a snapshot would copy a group that changes at every turn of a {@code -+b} loop.
     */
    Iterable<Entry> current(Literal l) {
        Group g = group(l);
        return g == null ? List.of() : g.entries;
    }

    /**
     * {@return the argument when it is a constant that unifies only with itself (an atom without
     * annotations, a number, a string), or null}
     */
    private static Object key(Term arg, NumberKey probe) {
        if (arg instanceof Literal a) {
            return a.isAtom() ? a : null;
        }
        if (arg instanceof NumberTerm n) {
            return probe == null ? new NumberKey(n.value()) : probe.set(n.value());
        }
        return arg instanceof StringTerm ? arg : null;
    }

    /** The number key of lookups (one mutable probe, as {@link #probe}). */
    private final NumberKey numberProbe = new NumberKey(0);

    /** A number as a key: a double's own hash puts whole numbers in few buckets. */
    private static final class NumberKey {
        private double value;

        NumberKey(double value) {
            set(value);
        }

        NumberKey set(double v) {
            value = v + 0.0; // -0.0 is 0.0
            return this;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof NumberKey k && k.value == value;
        }

        @Override
        public int hashCode() {
            long bits = Double.doubleToLongBits(value) * 0x9E3779B97F4A7C15L;
            return (int) (bits ^ (bits >>> 32));
        }
    }

    /** {@return the stored fact with exactly these arguments (any annotations), or null} */
    public Literal fact(Literal l) {
        var g = group(l);
        if (g == null) {
            return null;
        }
        Entry e = g.fact(l.args());
        return e == null ? null : e.literal;
    }

    /** Sees the belief base one predicate at a time (see {@link #forEachGroup}). */
    public interface GroupVisitor {
        /**
         * @param group the predicate's group, an object of its own
         * @param changedAt the belief base's change count at the group's last change: the same group
         *        with the same count holds the same entries, in the same order, each with the same literal
         * @param entries its entries in order, read only, as they are (not a snapshot)
         */
        void visit(Object group, long changedAt, Collection<Entry> entries);
    }

    /**
     * Visits every group in order; {@link #all()} is their entries one after the other. The mind
     * probe prints again only the groups whose count moved since its last capture.
     */
    public void forEachGroup(GroupVisitor v) {
        for (Group g : groups.values()) {
            v.visit(g, g.changedAt, g.readOnly);
        }
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

    /**
     * {@return how many changes the belief base has had} The same count means the same entries in
     * the same order, each with the same literal object (the mind probe walks the beliefs again
     * only when it moved).
     */
    public long changes() {
        return changes;
    }

    public void addRule(Rule rule, boolean atEnd) {
        Group g = groupFor(rule.head());
        g.add(new Entry(rule), atEnd);
        size++;
        changed(g);
    }

    /**
     * Adds a ground belief. {@return the literal to announce in a {@code +b} event, or null when
     * nothing changed (the belief was there with all these annotations)}
     */
    public Literal add(Literal l, boolean atEnd) {
        var group = groupFor(l);
        int hash = FactIndex.hash(l.args());
        Entry known = group.facts.get(l.args(), hash);
        if (known != null) {
            Literal fresh = BeliefAnnotations.merge(known, l);
            if (fresh != null) {
                changed(group);
            }
            return fresh;
        }
        Entry e = new Entry(l);
        group.facts.add(e, hash);
        group.add(e, atEnd);
        size++;
        changed(group);
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
        Entry e = group.fact(stored.args());
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
        Entry e = group.fact(removal.args());
        if (e == null || !BeliefAnnotations.containsAll(e.literal.annots(), removal.annots())) {
            return null;
        }
        return removeAnnots(group, e, removal);
    }

    private Literal removeAnnots(Group group, Entry e, Literal removal) {
        Literal stored = e.literal;
        if (!BeliefAnnotations.keepsSource(stored.annots(), removal.annots())) {
            removeFromGroup(group, e, stored);
            return stored;
        }
        group.snapshot = null;
        changed(group);
        var left = new ArrayList<Term>(stored.annots());
        left.removeAll(removal.annots());
        e.literal = stored.withAnnots(left);
        return removal;
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

    /**
     * {@link #removeEntry removeEntry(stored)} then {@link #add add(l, false)} in one step, where the
     * stored fact is the only entry of its predicate and {@code l} is of the same predicate (an
     * observable property's new value): the group stays, and moves to the end of the groups' order
     * as removing and adding would (the newest group stays where it is), with the same change
     * count. {@return true when done; false when it is not that case, and nothing changed}
     */
    public boolean replace(Literal stored, Literal l) {
        Group group = group(stored);
        Entry e = group == null || group.entries.size() != 1 ? null : group.entries.peekFirst();
        if (e == null || e.rule != null || !probe.set(l).equals(group.key) || (e.literal != stored && !e.literal.equals(stored))) {
            return false;
        }
        group.remove(e);
        changed(group);
        if (group != newest) {
            // removing the last entry takes the group out of the map (and the empty newest group
            // parked there goes when a group is added): adding puts it back as the newest, at the end
            groups.remove(group.key);
            if (parked != null) {
                groups.remove(parked.key);
                spare = parked;
                parked = null;
            }
            groups.put(group.key, group);
            newest = group;
        }
        Entry fresh = new Entry(l);
        group.facts.add(fresh, FactIndex.hash(l.args()));
        group.add(fresh, false);
        changed(group);
        return true;
    }

    private void removeFromGroup(Group group, Entry e, Literal stored) {
        group.remove(e);
        size--;
        changed(group);
        if (group.entries.isEmpty()) {
            if (group == newest) {
                parked = group;
            } else {
                groups.remove(probe.set(stored));
                spare = group;
            }
        }
    }

    /**
     * {@return the namespaces the belief base has had, the default one as {@code default}} They come
     * in the order of Jason's belief base, a {@code ConcurrentHashMap} keyed by namespace atoms, so
     * that {@code .namespace(N)} and queries {@code N::b} enumerate them as Jason does.
     */
    public List<Term> namespaces() {
        int table = 16;
        while (knownNs.size() >= table * 3 / 4) {
            table *= 2;
        }
        int mask = table - 1;
        var out = new ArrayList<Term>(knownNs);
        // a stable sort: namespaces in one bin stay in order of arrival
        out.sort(Comparator.comparingInt(n -> jasonHash(n) & mask));
        return out;
    }

    /** Jason's hash of a namespace atom (functor's, plus the default namespace's for the others), spread as the map spreads it. */
    private static int jasonHash(Term ns) {
        int d = Literal.DEFAULT_NS_NAME.hashCode();
        int h = ns instanceof Literal l && !l.isDefaultNsName() ? l.functor().hashCode() + d : d;
        return (h ^ (h >>> 16)) & 0x7fffffff;
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
