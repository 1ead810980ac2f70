package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The variable bindings of a {@link Unifier}: parallel arrays searched linearly, since a plan
 * rarely has more than a handful of variables, with a hash index once there are many. Copying
 * (done for every candidate plan and every solution) is two array copies of the bindings in use;
 * empty bindings share one empty array, so a fresh or copied empty unifier allocates none.
 */
final class Bindings {
    private static final int INDEX_FROM = 24;
    private static final Var[] NO_KEYS = new Var[0];
    private static final Term[] NO_VALUES = new Term[0];
    private Var[] keys;
    private Term[] values;
    private int size;
    private HashMap<Var, Integer> index;

    Bindings() {
        keys = NO_KEYS;
        values = NO_VALUES;
    }

    private Bindings(Bindings other) {
        copyFrom(other);
    }

    /** Copies the bindings in use, with room for a few more (solutions usually bind some). */
    private void copyFrom(Bindings other) {
        size = other.size;
        if (size == 0) {
            keys = NO_KEYS;
            values = NO_VALUES;
        } else {
            keys = Arrays.copyOf(other.keys, size + 4);
            values = Arrays.copyOf(other.values, size + 4);
        }
        index = other.index == null ? null : new HashMap<>(other.index);
    }

    Bindings copy() {
        return new Bindings(this);
    }

    private int indexOf(Var v) {
        if (index != null) {
            Integer i = index.get(v);
            return i == null ? -1 : i;
        }
        for (int i = size - 1; i >= 0; i--) {
            Var k = keys[i];
            if (k == v || k.equals(v)) {
                return i;
            }
        }
        return -1;
    }

    Term get(Var v) {
        int i = indexOf(v);
        return i < 0 ? null : values[i];
    }

    void put(Var v, Term t) {
        int i = indexOf(v);
        if (i >= 0) {
            values[i] = t;
            return;
        }
        if (size == keys.length) {
            keys = Arrays.copyOf(keys, Math.max(4, size * 2));
            values = Arrays.copyOf(values, keys.length);
        }
        keys[size] = v;
        values[size] = t;
        if (index != null) {
            index.put(v, size);
        } else if (size + 1 >= INDEX_FROM) {
            index = new HashMap<>();
            for (int k = 0; k <= size; k++) {
                index.put(keys[k], k);
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
            keys[i] = keys[last];
            values[i] = values[last];
            if (index != null) {
                index.put(keys[i], i);
            }
        }
        keys[last] = null;
        values[last] = null;
        size = last;
    }

    /** Replaces these bindings with a copy of another's, in the arrays already here when they fit. */
    void setFrom(Bindings other) {
        int n = other.size;
        if (n == 0 || n > keys.length) {
            copyFrom(other);
            return;
        }
        System.arraycopy(other.keys, 0, keys, 0, n);
        System.arraycopy(other.values, 0, values, 0, n);
        Arrays.fill(keys, n, size > n ? size : n, null);
        Arrays.fill(values, n, size > n ? size : n, null);
        size = n;
        index = other.index == null ? null : new HashMap<>(other.index);
    }

    int size() {
        return size;
    }

    /**
     * Forgets the bindings made since there were {@code mark}: unification only appends (it binds
     * unbound variables), so undoing it is cutting the arrays back.
     */
    void truncate(int mark) {
        for (int i = size - 1; i >= mark; i--) {
            if (index != null) {
                index.remove(keys[i]);
            }
            keys[i] = null;
            values[i] = null;
        }
        size = Math.min(size, mark);
    }

    boolean isEmpty() {
        return size == 0;
    }

    Map<Var, Term> asMap() {
        var m = new LinkedHashMap<Var, Term>();
        for (int i = 0; i < size; i++) {
            m.put(keys[i], values[i]);
        }
        return m;
    }
}
