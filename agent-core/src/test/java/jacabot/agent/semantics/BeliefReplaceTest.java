package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * An observable property's new value replaces its belief in one step ({@code BeliefBase.replace},
 * README "How the interpreter is fast"): the belief base must end exactly as removing the old
 * belief and adding the new one leaves it, the groups' order included (the step log prints the
 * beliefs in that order), with the same change counts.
 */
class BeliefReplaceTest {
    private static final String[] FUNCTORS = {"orientation", "location", "battery", "obstacle", "p"};

    private static Literal fact(String f, int v) {
        return Literal.of(f, new NumberTerm(v)).addAnnot(Literal.SOURCE_PERCEPT);
    }

    /** The entries group by group, each with its group's change count, as the mind probe sees them. */
    private static List<String> seen(BeliefBase base) {
        var out = new ArrayList<String>();
        base.forEachGroup((group, changedAt, entries) -> {
            var texts = new ArrayList<String>();
            entries.forEach(e -> texts.add(e.rule() != null ? e.rule().toString() : e.literal().toString()));
            out.add(changedAt + " " + texts);
        });
        out.add("size " + base.size() + ", changes " + base.changes());
        return out;
    }

    @Test
    void replacingIsRemovingThenAddingInEveryStateOfTheBase() {
        var random = new Random(42);
        int fast = 0;
        for (int run = 0; run < 200; run++) {
            var replaced = new BeliefBase();
            var general = new BeliefBase();
            for (int op = 0; op < 60; op++) {
                String f = FUNCTORS[random.nextInt(FUNCTORS.length)];
                int kind = random.nextInt(10);
                if (kind < 3) {
                    Literal l = fact(f, random.nextInt(4));
                    boolean atEnd = random.nextBoolean();
                    replaced.add(l, atEnd);
                    general.add(l, atEnd);
                } else if (kind < 5) {
                    Literal l = fact(f, random.nextInt(4));
                    replaced.removeEntry(l);
                    general.removeEntry(l);
                } else if (kind == 5 && random.nextInt(4) == 0) {
                    // a rule in a group: no belief of that predicate is replaced in one step
                    var rule = new Rule(Literal.of(f, new Var("X")), Literal.TRUE);
                    boolean atEnd = random.nextBoolean();
                    replaced.addRule(rule, atEnd);
                    general.addRule(rule, atEnd);
                } else {
                    // a property's update: the old value (there or not) replaced by another, maybe of another predicate
                    Literal old = fact(f, random.nextInt(4));
                    Literal now = random.nextInt(8) == 0 ? fact(FUNCTORS[random.nextInt(FUNCTORS.length)], 7)
                            : fact(f, random.nextInt(4));
                    if (replaced.replace(old, now)) {
                        fast++;
                    } else {
                        replaced.removeEntry(old);
                        replaced.add(now, false);
                    }
                    general.removeEntry(old);
                    general.add(now, false);
                }
                assertEquals(seen(general), seen(replaced), "run " + run + ", operation " + op);
                assertEquals(general.beliefs(), replaced.beliefs());
            }
        }
        assertTrue(fast > 150, "the one-step case was exercised: " + fast);
    }

    @Test
    void onlyTheOnlyBeliefOfItsPredicateIsReplacedInOneStep() {
        var base = new BeliefBase();
        base.add(fact("a", 1), false);
        base.add(fact("b", 1), false);
        base.add(fact("b", 2), false);
        assertFalse(base.replace(fact("b", 1), fact("b", 3)), "two beliefs of b");
        assertFalse(base.replace(fact("a", 2), fact("a", 3)), "a(2) is not there");
        assertFalse(base.replace(fact("a", 1), fact("c", 3)), "another predicate");
        assertEquals(3, base.size());
        assertTrue(base.replace(fact("a", 1), fact("a", 3)));
        assertEquals(List.of(fact("b", 2), fact("b", 1), fact("a", 3)), base.beliefs(), "a's group moved to the end");
    }

    @Test
    void anEmptyNewestGroupParkedInTheBaseGoesAsWhenAdding() {
        var replaced = new BeliefBase();
        var general = new BeliefBase();
        for (BeliefBase base : List.of(replaced, general)) {
            base.add(fact("a", 1), false);
            base.add(fact("c", 1), false);
            base.add(fact("b", 1), false);
            base.removeEntry(fact("b", 1)); // b's group, the newest, is left empty in the map
        }
        assertTrue(replaced.replace(fact("a", 1), fact("a", 2)));
        general.removeEntry(fact("a", 1));
        general.add(fact("a", 2), false);
        assertEquals(seen(general), seen(replaced));
        assertTrue(replaced.replace(fact("a", 2), fact("a", 3)), "a is the newest now");
        general.removeEntry(fact("a", 2));
        general.add(fact("a", 3), false);
        assertEquals(seen(general), seen(replaced));
        assertEquals(List.of(fact("c", 1), fact("a", 3)), replaced.beliefs());
    }
}
