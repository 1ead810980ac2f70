package jacabot.experiments;

import java.util.Arrays;

/**
 * A priority queue of grid cells by cost, lowest first, held in two arrays of primitives: the
 * binary heap of {@link java.util.PriorityQueue} (the same sifting up and down), so cells of equal
 * cost come out in the order a {@code PriorityQueue} with a comparator of the costs gives them.
 * {@link RouteMap}'s A* takes its routes from that order, and the recorded runs depend on it.
 */
final class CellQueue {
    private double[] keys = new double[64];
    private int[] cells = new int[64];
    private int size;

    boolean isEmpty() {
        return size == 0;
    }

    void clear() {
        size = 0;
    }

    /** Adds {@code cell} at {@code key}: sifted up from the end, as {@code PriorityQueue.offer}. */
    void add(double key, int cell) {
        if (size == keys.length) {
            keys = Arrays.copyOf(keys, size * 2);
            cells = Arrays.copyOf(cells, size * 2);
        }
        int k = size++;
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            if (Double.compare(key, keys[parent]) >= 0) {
                break;
            }
            keys[k] = keys[parent];
            cells[k] = cells[parent];
            k = parent;
        }
        keys[k] = key;
        cells[k] = cell;
    }

    /** {@return the cell of the lowest key, removed}: the last entry sifted down from the root, as {@code PriorityQueue.poll}. */
    int poll() {
        int result = cells[0];
        int n = --size;
        if (n > 0) {
            double key = keys[n];
            int cell = cells[n];
            int k = 0, half = n >>> 1;
            while (k < half) {
                int child = 2 * k + 1, right = child + 1;
                if (right < n && Double.compare(keys[child], keys[right]) > 0) {
                    child = right;
                }
                if (Double.compare(key, keys[child]) <= 0) {
                    break;
                }
                keys[k] = keys[child];
                cells[k] = cells[child];
                k = child;
            }
            keys[k] = key;
            cells[k] = cell;
        }
        return result;
    }
}
