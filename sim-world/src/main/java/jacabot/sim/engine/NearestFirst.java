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

    /** Adds the hit on the object of the given index in the world's order. */
    void add(RayHit hit, int index) {
        int at = hits.size();
        while (at > 0 && (hits.get(at - 1).distance() > hit.distance()
                || hits.get(at - 1).distance() == hit.distance() && indices[at - 1] > index)) {
            at--;
        }
        if (hits.size() == indices.length) {
            indices = Arrays.copyOf(indices, 2 * indices.length);
        }
        System.arraycopy(indices, at, indices, at + 1, hits.size() - at);
        indices[at] = index;
        hits.add(at, hit);
    }

    /** {@return the hits, nearest first} */
    List<RayHit> list() {
        return hits;
    }
}
