package jacabot.sim.engine;

import jacabot.sim.device.RayHit;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * One ray's hits, nearest first, a tie in the world's order (the objects' index): the order
 * {@code castAll} gives when it casts the objects in the world's order, kept when a fan casts
 * them in another order (nearest bound first). Internal to sim-world.
 */
final class NearestFirst {
    private final List<RayHit> hits = new ArrayList<>(4);
    private int[] indices = new int[4];
    /** Each hit's farthest distance: its own, or its bracket's far end (see {@link #add(RayHit, int, double)}). */
    private double[] far = new double[4];

    /** Adds the hit on the object of the given index in the world's order. */
    void add(RayHit hit, int index) {
        add(hit, index, hit.distance());
    }

    /**
     * Adds a hit whose true distance lies between its own and {@code far}: it is ordered by its own,
     * which gives the true order while {@link #apart} holds.
     */
    void add(RayHit hit, int index, double far) {
        int at = hits.size();
        while (at > 0 && (hits.get(at - 1).distance() > hit.distance()
                || hits.get(at - 1).distance() == hit.distance() && indices[at - 1] > index)) {
            at--;
        }
        if (hits.size() == indices.length) {
            indices = Arrays.copyOf(indices, 2 * indices.length);
            this.far = Arrays.copyOf(this.far, 2 * this.far.length);
        }
        System.arraycopy(indices, at, indices, at + 1, hits.size() - at);
        System.arraycopy(this.far, at, this.far, at + 1, hits.size() - at);
        indices[at] = index;
        this.far[at] = far;
        hits.add(at, hit);
    }

    /**
     * {@return whether no bracket meets another hit's distance or bracket}: then any distances within
     * the brackets give the order of the true ones (the brackets are sorted by their near ends, so
     * each need only stay short of the next)
     */
    boolean apart() {
        for (int i = 0; i + 1 < hits.size(); i++) {
            boolean bracketed = far[i] != hits.get(i).distance() || far[i + 1] != hits.get(i + 1).distance();
            if (bracketed && far[i] >= hits.get(i + 1).distance()) {
                return false;
            }
        }
        return true;
    }

    /** {@return the hits, nearest first} */
    List<RayHit> list() {
        return hits;
    }
}
