package jacabot.app.inspector;

import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
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
 * Not thread-safe: the agent's thread captures.
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

    /** The belief base's change count at the last capture. */
    private long changes = -1;
    private List<MindState.Belief> last = List.of();
    /** Whether some group of the last list holds an entry printed anew at every capture. */
    private boolean holdsObjects;
    private IdentityHashMap<Object, Shown> groups = new IdentityHashMap<>();

    /** {@return the beliefs and rules, in the belief base's order} */
    List<MindState.Belief> of(BeliefBase base) {
        if (base.changes() == changes && !holdsObjects) {
            return last;
        }
        var beliefs = new ArrayList<MindState.Belief>(base.size());
        var now = new IdentityHashMap<Object, Shown>();
        boolean[] objects = {false};
        base.forEachGroup((group, changedAt, entries) -> {
            Shown was = groups.get(group);
            Shown s = was != null && was.changedAt() == changedAt && was.stable() ? was : show(changedAt, entries, was);
            now.put(group, s);
            for (MindState.Belief b : s.beliefs()) {
                beliefs.add(b);
            }
            objects[0] |= !s.stable();
        });
        groups = now;
        changes = base.changes();
        holdsObjects = objects[0];
        last = List.copyOf(beliefs);
        return last;
    }

    /** {@return a group's entries as beliefs, those {@code was} showed (if any) as the same objects} */
    private static Shown show(long changedAt, Collection<BeliefBase.Entry> entries, Shown was) {
        var keys = new Object[entries.size()];
        var beliefs = new MindState.Belief[entries.size()];
        boolean stable = true;
        int k = 0;
        for (BeliefBase.Entry e : entries) {
            Object key = e.rule() != null ? e.rule() : e.literal();
            MindState.Belief b = was == null ? null : was.find(key);
            if (b == null) {
                b = e.rule() != null ? rule(e.rule()) : belief(e.literal());
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
        var sources = new ArrayList<String>();
        var annots = new ArrayList<String>();
        for (Term a : l.annots()) {
            if (a instanceof Literal s && s.functor().equals("source") && s.arity() == 1) {
                sources.add(s.arg(0).toString());
            } else {
                annots.add(a.toString());
            }
        }
        return new MindState.Belief(l.withoutAnnots().toString(), sources, annots);
    }
}
