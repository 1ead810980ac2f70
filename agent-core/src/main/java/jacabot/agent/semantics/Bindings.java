package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The variable bindings of a {@link Unifier}: one array of variable and value pairs, searched
 * linearly while a plan's handful of variables is all there is, and through an open-addressing
 * table of positions once there are many (a deep proof binds thousands; the table allocates
 * nothing per binding). Copying (done for every candidate plan and every solution) is one array
 * copy of the pairs in use; empty bindings share one empty array, so a fresh or copied empty
 * unifier allocates none. Bindings only append, except {@link #remove}, so the array is also the
 * trail that backtracking cuts back ({@link #truncate}).
 */
final class Bindings {
    private static final int INDEX_FROM = 24;
    private static final Object[] NONE = new Object[0];
    /** Variable {@code i} at {@code 2i}, its value at {@code 2i + 1}. */
    private Object[] pairs;
    private int size;
    /** Linear probing by variable: a slot holds a position + 1, or 0 when empty; null while small. */
    private int[] table;

    Bindings() {
        pairs = NONE;
    }

    private Bindings(Bindings other) {
        copyFrom(other);
    }

    /** Copies the pairs in use, with room for two more (solutions usually bind few). */
    private void copyFrom(Bindings other) {
        size = other.size;
        pairs = size == 0 ? NONE : Arrays.copyOf(other.pairs, 2 * (size + 2));
        table = other.table == null ? null : other.table.clone();
    }

    /** {@return a copy of the first {@code n} bindings} */
    Bindings prefix(int n) {
        var b = new Bindings();
        if (n > 0) {
            b.pairs = Arrays.copyOf(pairs, 2 * (n + 2));
            Arrays.fill(b.pairs, 2 * n, b.pairs.length, null);
            b.size = n;
            if (n >= INDEX_FROM) {
                b.rebuild(n);
            }
        }
        return b;
    }

    Bindings copy() {
        return new Bindings(this);
    }

    private static int hash(Var v) {
        int h = v.hashCode() * 0x9E3779B9;
        return h ^ (h >>> 16);
    }

    private int indexOf(Var v) {
        Object[] p = pairs;
        if (table != null) {
            int mask = table.length - 1;
            for (int i = hash(v) & mask; ; i = (i + 1) & mask) {
                int at = table[i];
                if (at == 0) {
                    return -1;
                }
                Var k = (Var) p[2 * (at - 1)];
                if (k == v || k.equals(v)) {
                    return at - 1;
                }
            }
        }
        for (int i = size - 1; i >= 0; i--) {
            // as a Var, the call binds to Var.equals (no dispatch on Object's)
            Var k = (Var) p[2 * i];
            if (k == v || k.equals(v)) {
                return i;
            }
        }
        return -1;
    }

    /** Makes a table for the first {@code n} pairs, at most half full. */
    private void rebuild(int n) {
        int length = 64;
        while (length < 2 * n) {
            length <<= 1;
        }
        table = new int[length];
        for (int k = 0; k < n; k++) {
            tableAdd((Var) pairs[2 * k], k);
        }
    }

    private void tableAdd(Var v, int position) {
        int mask = table.length - 1;
        int i = hash(v) & mask;
        while (table[i] != 0) {
            i = (i + 1) & mask;
        }
        table[i] = position + 1;
    }

    /** Frees the variable's slot, shifting back what follows so that no search stops short. */
    private void tableRemove(Var v, int position) {
        int mask = table.length - 1;
        int i = hash(v) & mask;
        while (table[i] != position + 1) {
            i = (i + 1) & mask;
        }
        for (int j = (i + 1) & mask; table[j] != 0; j = (j + 1) & mask) {
            int home = hash((Var) pairs[2 * (table[j] - 1)]) & mask;
            // the entry at j may fill the hole at i when i lies between its home and j
            if (((j - home) & mask) >= ((j - i) & mask)) {
                table[i] = table[j];
                i = j;
            }
        }
        table[i] = 0;
    }

    /** {@return the position of the variable's binding (bindings only append), or -1 when unbound} */
    int position(Var v) {
        return indexOf(v);
    }

    /** {@return whether the pairs in use are those of {@code other} (a {@link #suffix}(0)), object for object} */
    boolean samePairs(Object[] other) {
        if (other.length != 2 * size) {
            return false;
        }
        for (int i = 0; i < other.length; i++) {
            if (pairs[i] != other[i]) {
                return false;
            }
        }
        return true;
    }

    /** {@return the pairs bound since there were {@code mark}, to be {@link #append}ed later} */
    Object[] suffix(int mark) {
        // an internal action's unifier is an extension of the one it was given: never shorter
        return mark >= size ? NONE : Arrays.copyOfRange(pairs, 2 * mark, 2 * size);
    }

    /** Binds the first {@code n} slots of pairs of a {@link #suffix} again (its variables are unbound here). */
    void append(Object[] more, int n) {
        for (int i = 0; i < n; i += 2) {
            put((Var) more[i], (Term) more[i + 1]);
        }
    }

    Term get(Var v) {
        int i = indexOf(v);
        return i < 0 ? null : (Term) pairs[2 * i + 1];
    }

    void put(Var v, Term t) {
        int i = indexOf(v);
        if (i >= 0) {
            pairs[2 * i + 1] = t;
            return;
        }
        if (2 * size == pairs.length) {
            pairs = Arrays.copyOf(pairs, Math.max(8, 4 * size));
        }
        pairs[2 * size] = v;
        pairs[2 * size + 1] = t;
        if (table != null && 2 * (size + 1) <= table.length) {
            tableAdd(v, size);
        } else if (size + 1 >= INDEX_FROM) {
            rebuild(size + 1);
        }
        size++;
    }

    void remove(Var v) {
        int i = indexOf(v);
        if (i < 0) {
            return;
        }
        int last = size - 1;
        if (table != null) {
            tableRemove(v, i);
        }
        if (i != last) {
            Var moved = (Var) pairs[2 * last];
            if (table != null) {
                tableRemove(moved, last);
            }
            pairs[2 * i] = moved;
            pairs[2 * i + 1] = pairs[2 * last + 1];
            if (table != null) {
                tableAdd(moved, i);
            }
        }
        pairs[2 * last] = null;
        pairs[2 * last + 1] = null;
        size = last;
    }

    /** Replaces these bindings with a copy of another's, in the array already here when it fits. */
    void setFrom(Bindings other) {
        int n = other.size;
        if (n == 0 || 2 * n > pairs.length) {
            copyFrom(other);
            return;
        }
        System.arraycopy(other.pairs, 0, pairs, 0, 2 * n);
        if (size > n) {
            Arrays.fill(pairs, 2 * n, 2 * size, null);
        }
        size = n;
        table = other.table == null ? null : other.table.clone();
    }

    /** Replaces these bindings with a copy of another's first {@code n}, in the array already here when it fits. */
    void setFromPrefix(Bindings other, int n) {
        if (2 * n > pairs.length) {
            pairs = new Object[2 * (n + 2)];
        }
        System.arraycopy(other.pairs, 0, pairs, 0, 2 * n);
        if (size > n) {
            Arrays.fill(pairs, 2 * n, 2 * size, null);
        }
        size = n;
        table = null;
        if (n >= INDEX_FROM) {
            rebuild(n);
        }
    }

    int size() {
        return size;
    }

    /**
     * Forgets the bindings made since there were {@code mark}: unification only appends (it binds
     * unbound variables), so undoing it is cutting the array back.
     */
    void truncate(int mark) {
        if (table != null && mark < INDEX_FROM) {
            table = null;
        }
        for (int i = size - 1; i >= mark; i--) {
            if (table != null) {
                tableRemove((Var) pairs[2 * i], i);
            }
            pairs[2 * i] = null;
            pairs[2 * i + 1] = null;
        }
        size = Math.min(size, mark);
    }

    boolean isEmpty() {
        return size == 0;
    }

    Map<Var, Term> asMap() {
        var m = new LinkedHashMap<Var, Term>();
        for (int i = 0; i < size; i++) {
            m.put((Var) pairs[2 * i], (Term) pairs[2 * i + 1]);
        }
        return m;
    }
}
