package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

/**
 * The order in which Jason's {@code Unifier} lists its bindings: a {@code java.util.HashMap} keyed by
 * variable, whose hash is its name's, so the order is that of the names' buckets (insertion order
 * within one). Programs print it through {@code .intention}, and Jason's warning for an unhandled
 * failure prints it, so it is reproduced, not guessed. (A map Jason cloned has fewer buckets; the
 * order of its bindings then differs, which is not followed.)
 */
public final class JasonHashOrder {
    private JasonHashOrder() {
    }

    /** {@return the variable's name in Jason: as written, or {@code _N} for an unnamed or fresh one} */
    public static String jasonName(Var v) {
        return v.toString();
    }

    /** {@return the unifier as Jason prints it: {@code {X=a, Y=1}}, in its hash map's order} */
    public static String text(Unifier u) {
        var sb = new StringBuilder("{");
        for (var e : of(u.bindings())) {
            sb.append(sb.length() > 1 ? ", " : "").append(e.getKey()).append('=').append(e.getValue());
        }
        return sb.append('}').toString();
    }

    /** {@return the bindings, given in insertion order, in the order Jason's hash map iterates them} */
    public static List<Map.Entry<Var, Term>> of(Map<Var, Term> bindings) {
        int n = bindings.size();
        // a map that grew by insertion has 16 buckets up to 12 entries, and doubles past 3/4 full
        int buckets = 16;
        while (n > buckets * 3 / 4) {
            buckets *= 2;
        }
        int mask = buckets - 1;
        var entries = new ArrayList<>(bindings.entrySet());
        // stable: entries of one bucket keep their insertion order, as in the bucket's list
        entries.sort(Comparator.comparingInt(e -> bucket(jasonName(e.getKey()), mask)));
        return entries;
    }

    private static int bucket(String name, int mask) {
        int h = name.hashCode();
        return (h ^ (h >>> 16)) & mask;
    }
}
