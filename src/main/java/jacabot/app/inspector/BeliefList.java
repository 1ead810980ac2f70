package jacabot.app.inspector;

import java.util.AbstractList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.NoSuchElementException;
import java.util.RandomAccess;

/**
 * The beliefs section of a {@link MindState}: the belief base's predicates (groups) in order, each
 * as the array of beliefs a capture showed for it. Immutable (the arrays are never written once
 * shown), so a capture shares the arrays of the groups that did not change instead of copying
 * every belief into a new list, and the step log's writer compares two captures group by group
 * ({@link #group}, {@link #groups}). A group's array is the same object in two captures exactly
 * when the capture reused how the last one showed that group.
 */
public final class BeliefList extends AbstractList<MindState.Belief> implements RandomAccess {
    static final BeliefList EMPTY = new BeliefList(new MindState.Belief[0][], 0);

    private final MindState.Belief[][] groups;
    /** The index after each group's last belief. */
    private final int[] ends;

    /**
     * @param groups the groups' beliefs, the first {@code count} of them used (the array itself
     *        when that is all of it); no array is written afterwards
     */
    BeliefList(MindState.Belief[][] groups, int count) {
        if (groups.length != count) {
            // not Arrays.copyOf: for an array of another class than Object[] it goes through
            // Array.newInstance, a call into the VM with C1 only (gradle run's setting)
            var some = new MindState.Belief[count][];
            System.arraycopy(groups, 0, some, 0, count);
            groups = some;
        }
        this.groups = groups;
        this.ends = new int[count];
        int n = 0;
        for (int g = 0; g < count; g++) {
            n += groups[g].length;
            ends[g] = n;
        }
    }

    /** {@return how many groups} (an empty group is kept: its position is the belief base's) */
    public int groups() {
        return groups.length;
    }

    /**
     * {@return where {@code group} (an array of this list's, by identity) is, looked for from
     * {@code from} on first, then before it; -1: not there} (see {@link #indexFrom})
     */
    public int indexOfGroup(MindState.Belief[] group, int from) {
        return indexFrom(groups, groups.length, group, from);
    }

    /**
     * {@return where {@code x} is among the first {@code n} of {@code items}, by identity, or -1}
     * Looked for where the last capture had it or a little further on (in place, or past items that
     * moved or went), then before that (moved to the end since): the belief base moves a changed
     * property's group to the end, so a walk in order finds each at once.
     */
    static int indexFrom(Object[] items, int n, Object x, int from) {
        for (int k = from; k < n; k++) {
            if (items[k] == x) {
                return k;
            }
        }
        for (int k = 0; k < from && k < n; k++) {
            if (items[k] == x) {
                return k;
            }
        }
        return -1;
    }

    /** {@return group {@code g}'s beliefs, read only: the same array in two lists when the capture kept that group} */
    public MindState.Belief[] group(int g) {
        return groups[g];
    }

    @Override
    public int size() {
        return ends.length == 0 ? 0 : ends[ends.length - 1];
    }

    @Override
    public MindState.Belief get(int index) {
        if (index < 0 || index >= size()) {
            throw new IndexOutOfBoundsException(index);
        }
        int g = Arrays.binarySearch(ends, index + 1);
        if (g < 0) {
            g = -g - 1;
        } else {
            while (g > 0 && ends[g - 1] == index + 1) {
                g--; // past empty groups ending at the same index
            }
        }
        return groups[g][index - (g == 0 ? 0 : ends[g - 1])];
    }

    @Override
    public Iterator<MindState.Belief> iterator() {
        return new Iterator<>() {
            private int g;
            private int i;

            @Override
            public boolean hasNext() {
                while (g < groups.length && i >= groups[g].length) {
                    g++;
                    i = 0;
                }
                return g < groups.length;
            }

            @Override
            public MindState.Belief next() {
                if (!hasNext()) {
                    throw new NoSuchElementException();
                }
                return groups[g][i++];
            }
        };
    }
}
