package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The variable bindings of a {@link Unifier}: one array of variable and value pairs searched
 * linearly, since a plan rarely has more than a handful of variables, with a hash index once
 * there are many. Copying (done for every candidate plan and every solution) is one array copy of
 * the pairs in use; empty bindings share one empty array, so a fresh or copied empty unifier
 * allocates none.
 */
final class Bindings {
    private static final int INDEX_FROM = 24;
    private static final Object[] NONE = new Object[0];
    /** Variable {@code i} at {@code 2i}, its value at {@code 2i + 1}. */
    private Object[] pairs;
    private int size;
    private HashMap<Var, Integer> index;

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
        index = other.index == null ? null : new HashMap<>(other.index);
    }

    /** {@return a copy of the first {@code n} bindings} */
    Bindings prefix(int n) {
        var b = new Bindings();
        if (n > 0) {
            b.pairs = Arrays.copyOf(pairs, 2 * (n + 2));
            Arrays.fill(b.pairs, 2 * n, b.pairs.length, null);
            b.size = n;
            if (n >= INDEX_FROM) {
                b.index = new HashMap<>();
                for (int k = 0; k < n; k++) {
                    b.index.put((Var) pairs[2 * k], k);
                }
            }
        }
        return b;
    }

    Bindings copy() {
        return new Bindings(this);
    }

    private int indexOf(Var v) {
        if (index != null) {
            Integer i = index.get(v);
            return i == null ? -1 : i;
        }
        Object[] p = pairs;
        for (int i = size - 1; i >= 0; i--) {
            Object k = p[2 * i];
            if (k == v || k.equals(v)) {
                return i;
            }
        }
        return -1;
    }

    /** {@return the position of the variable's binding (bindings only append), or -1 when unbound} */
    int position(Var v) {
        return indexOf(v);
    }

    /** {@return the pairs bound since there were {@code mark}, to be {@link #append}ed later} */
    Object[] suffix(int mark) {
        return Arrays.copyOfRange(pairs, 2 * mark, 2 * size);
    }

    /** Binds the pairs of a {@link #suffix} again (its variables are unbound here). */
    void append(Object[] more) {
        for (int i = 0; i < more.length; i += 2) {
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
        if (index != null) {
            index.put(v, size);
        } else if (size + 1 >= INDEX_FROM) {
            index = new HashMap<>();
            for (int k = 0; k <= size; k++) {
                index.put((Var) pairs[2 * k], k);
            }
        }
        size++;
    }

    void remove(Var v) {
        int i = indexOf(v);
        if (i < 0) {
            return;
        }
        int last = size - 1;
        if (index != null) {
            index.remove(v);
        }
        if (i != last) {
            pairs[2 * i] = pairs[2 * last];
            pairs[2 * i + 1] = pairs[2 * last + 1];
            if (index != null) {
                index.put((Var) pairs[2 * i], i);
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
        index = other.index == null ? null : new HashMap<>(other.index);
    }

    int size() {
        return size;
    }

    /**
     * Forgets the bindings made since there were {@code mark}: unification only appends (it binds
     * unbound variables), so undoing it is cutting the array back.
     */
    void truncate(int mark) {
        for (int i = size - 1; i >= mark; i--) {
            if (index != null) {
                index.remove((Var) pairs[2 * i]);
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
