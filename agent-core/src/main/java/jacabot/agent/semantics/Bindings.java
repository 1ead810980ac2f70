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
 * (done for every candidate plan and every solution) is two array copies.
 */
final class Bindings {
    private static final int INDEX_FROM = 24;
    private Var[] keys;
    private Term[] values;
    private int size;
    private HashMap<Var, Integer> index;

    Bindings() {
        keys = new Var[8];
        values = new Term[8];
    }

    private Bindings(Bindings other) {
        keys = Arrays.copyOf(other.keys, Math.max(8, other.size + 4));
        values = Arrays.copyOf(other.values, keys.length);
        size = other.size;
        if (other.index != null) {
            index = new HashMap<>(other.index);
        }
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
            keys = Arrays.copyOf(keys, size * 2);
            values = Arrays.copyOf(values, size * 2);
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

    void setFrom(Bindings other) {
        keys = Arrays.copyOf(other.keys, Math.max(8, other.keys.length));
        values = Arrays.copyOf(other.values, keys.length);
        size = other.size;
        index = other.index == null ? null : new HashMap<>(other.index);
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
