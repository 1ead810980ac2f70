package jacabot.agent.semantics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class BindingsTest {

    /** Random binds, unbinds, cuts back, copies and prefixes against a map; past the size where the table takes over. */
    @Test
    void findsWhatAMapWouldThroughGrowthCutsAndRemovals() {
        var random = new Random(7);
        var b = new Bindings();
        var model = new ArrayList<Var>();
        var values = new LinkedHashMap<Var, Term>();
        long serial = 1;
        int largest = 0;
        for (int step = 0; step < 20_000; step++) {
            int op = random.nextInt(10);
            if (op < 7) {
                // few names, many serials: names collide in hash, as renamed rule variables do
                var v = new Var(List.of("X", "Y", "Z").get(random.nextInt(3)), serial++);
                b.put(v, new NumberTerm(step));
                model.add(v);
                values.put(v, new NumberTerm(step));
            } else if (op == 7 && !model.isEmpty()) {
                // mostly a few steps back, as backtracking goes, and now and then far back
                int mark = Math.max(0, model.size() - random.nextInt(6));
                if (random.nextInt(200) == 0) {
                    mark = random.nextInt(model.size() + 1);
                }
                b.truncate(mark);
                while (model.size() > mark) {
                    values.remove(model.remove(model.size() - 1));
                }
            } else if (op == 8 && !model.isEmpty()) {
                var v = model.get(random.nextInt(model.size()));
                b.remove(v);
                // the last binding takes the removed one's place
                int i = model.indexOf(v);
                var last = model.remove(model.size() - 1);
                if (last != v) {
                    model.set(i, last);
                }
                values.remove(v);
            } else if (!model.isEmpty()) {
                b = random.nextBoolean() ? b.copy() : b.prefix(model.size());
            }
            assertEquals(model.size(), b.size());
            largest = Math.max(largest, model.size());
            if (step % 50 == 0) {
                for (var v : values.keySet()) {
                    assertEquals(values.get(v), b.get(v), "step " + step);
                }
                assertEquals(null, b.get(new Var("X", serial + 1)));
            }
        }
        assertEquals(true, largest > 500, "largest " + largest);
    }
}
