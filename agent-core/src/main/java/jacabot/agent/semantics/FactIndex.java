package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import java.util.List;

/**
 * The facts of a belief group by their arguments: an open-addressing table of the entries
 * themselves, each keeping its arguments' hash. A hash map made a key and a node for every
 * belief added, and rehashed every node as a told receiver's facts grew.
 */
final class FactIndex {
    private BeliefBase.Entry[] slots = new BeliefBase.Entry[8];
    private int size;

    /**
     * The arguments' hash, mixed: a whole number's hash (a double's) has its low bits zero, so
     * the facts n(N) a receiver is told would crowd a few slots.
     */
    static int hash(List<Term> args) {
        return (int) ((args.hashCode() * 0x9E3779B97F4A7C15L) >>> 32);
    }

    /** {@return the fact with these arguments, or null} */
    BeliefBase.Entry get(List<Term> args) {
        return size == 0 ? null : get(args, hash(args));
    }

    /** As {@link #get(List)}, with the arguments' {@link #hash} known. */
    BeliefBase.Entry get(List<Term> args, int h) {
        if (size == 0) {
            return null;
        }
        BeliefBase.Entry[] s = slots;
        int mask = s.length - 1;
        for (int i = h & mask; ; i = (i + 1) & mask) {
            BeliefBase.Entry e = s[i];
            if (e == null) {
                return null;
            }
            if (e.argsHash == h && e.literal().args().equals(args)) {
                return e;
            }
        }
    }

    /** Adds a fact whose arguments (of this {@link #hash}) are not there yet. */
    void add(BeliefBase.Entry e, int argsHash) {
        e.argsHash = argsHash;
        if (2 * (size + 1) > slots.length) {
            grow();
        }
        place(slots, e);
        size++;
    }

    private static void place(BeliefBase.Entry[] s, BeliefBase.Entry e) {
        int mask = s.length - 1;
        int i = e.argsHash & mask;
        while (s[i] != null) {
            i = (i + 1) & mask;
        }
        s[i] = e;
    }

    private void grow() {
        var bigger = new BeliefBase.Entry[2 * slots.length];
        for (BeliefBase.Entry e : slots) {
            if (e != null) {
                place(bigger, e);
            }
        }
        slots = bigger;
    }

    /** Removes a fact (the entry itself); what follows it in its run moves back into the hole. */
    void remove(BeliefBase.Entry e) {
        BeliefBase.Entry[] s = slots;
        int mask = s.length - 1;
        int i = e.argsHash & mask;
        while (s[i] != e) {
            if (s[i] == null) {
                return;
            }
            i = (i + 1) & mask;
        }
        for (int j = (i + 1) & mask; s[j] != null; j = (j + 1) & mask) {
            int home = s[j].argsHash & mask;
            // the entry at j may fill the hole at i when i lies between its home and j
            if (((j - home) & mask) >= ((j - i) & mask)) {
                s[i] = s[j];
                i = j;
            }
        }
        s[i] = null;
        size--;
    }
}
