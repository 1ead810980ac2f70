package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * What the mind probe reads to print only what changed (README, "How the interpreter is fast"):
 * the belief base's change counts move at every change of an entry and only there, each group's
 * with it; a unifier tells whether its bindings are still those it gave.
 */
class ChangeTrackingTest {

    private static Literal b(int n, Literal... annots) {
        Literal l = Literal.of("b", new NumberTerm(n));
        for (Literal a : annots) {
            l = l.addAnnot(a);
        }
        return l;
    }

    /** {@return each group's change count, by its first entry's functor} */
    private static Map<String, Long> groups(BeliefBase base) {
        var out = new HashMap<String, Long>();
        base.forEachGroup((group, changedAt, entries) -> {
            if (!entries.isEmpty()) {
                out.put(entries.iterator().next().literal().functor(), changedAt);
            }
        });
        return out;
    }

    private static void assertChanges(BeliefBase base, String group, Consumer<BeliefBase> change) {
        long before = base.changes();
        Map<String, Long> groupsBefore = groups(base);
        change.accept(base);
        assertTrue(base.changes() > before, "the count moved");
        Map<String, Long> after = groups(base);
        for (var e : groupsBefore.entrySet()) {
            if (e.getKey().equals(group)) {
                assertNotEquals(e.getValue(), after.get(group), group + "'s count moved");
            } else {
                assertEquals(e.getValue(), after.get(e.getKey()), e.getKey() + "'s count kept");
            }
        }
    }

    @Test
    void everyChangeOfAnEntryMovesTheCountsOfTheBaseAndOfItsGroupOnly() {
        var base = new BeliefBase();
        base.add(Literal.of("other", new NumberTerm(0)).addAnnot(Literal.SOURCE_SELF), true);
        base.add(b(1, Literal.SOURCE_SELF), true);
        assertChanges(base, "b", bb -> bb.add(b(2, Literal.SOURCE_SELF), false));
        assertChanges(base, "b", bb -> bb.add(b(2, Literal.SOURCE_PERCEPT), true)); // annotations merged
        assertChanges(base, "b", bb -> bb.removeFact(b(2, Literal.SOURCE_PERCEPT))); // one source of two
        assertChanges(base, "b", bb -> bb.removeFact(b(2, Literal.SOURCE_SELF)));
        assertChanges(base, "other", bb -> bb.addRule(new Rule(Literal.of("other", new Var("X")), Literal.TRUE), true));

        long before = base.changes();
        assertNull(base.add(b(1, Literal.SOURCE_SELF), true), "nothing new");
        assertNull(base.removeFact(b(9, Literal.SOURCE_SELF)), "nothing to remove");
        base.candidates(b(1));
        assertEquals(before, base.changes(), "no change, no count");
    }

    @Test
    void theGroupsInOrderAreAllTheEntries() {
        var base = new BeliefBase();
        base.add(b(1, Literal.SOURCE_SELF), true);
        base.add(Literal.of("c", new NumberTerm(1)).addAnnot(Literal.SOURCE_SELF), true);
        base.add(b(2, Literal.SOURCE_SELF), false);
        var seen = new ArrayList<BeliefBase.Entry>();
        base.forEachGroup((group, changedAt, entries) -> seen.addAll(entries));
        assertEquals(base.all(), seen);
    }

    @Test
    void aUnifierTellsWhetherItsBindingsAreThoseItGave() {
        var u = new Unifier();
        Object[] empty = u.bindingsNow();
        assertTrue(u.hasBindings(empty));
        var x = new Var("X");
        u.bind(x, new NumberTerm(1));
        assertFalse(u.hasBindings(empty));
        Object[] one = u.bindingsNow();
        assertTrue(u.hasBindings(one));
        u.bind(x, new NumberTerm(1)); // an equal value, another object: printed again, as it may be
        assertFalse(u.hasBindings(one));
        Object[] again = u.bindingsNow();
        var copy = u.copy();
        assertTrue(copy.hasBindings(again), "a copy has the same bindings");
        u.unbind(x);
        assertFalse(u.hasBindings(again));
        u.setFrom(copy);
        assertTrue(u.hasBindings(again));
        assertEquals(List.of(x), List.copyOf(u.bindings().keySet()));
    }
}
