package jacabot.app.world;

import jacabot.sim.world.Footprint;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * The arena's floor while {@link WorldGenerator} draws a world: what is placed on it, the circles
 * kept clear of obstacles, and the random places found for new objects. Every place is drawn from
 * the generator's one random stream, in the order the generator asks, so that a seed gives the same
 * world text.
 */
final class Floor {
    private final SplittableRandom random;
    private double halfW, halfD, gap;
    private final List<Footprint> placed = new ArrayList<>();
    private final List<double[]> free = new ArrayList<>(); // circles (x, z, r) kept clear of obstacles

    Floor(SplittableRandom random) {
        this.random = random;
    }

    /** Empties the floor for a new draw of an arena of {@code halfW} by {@code halfD} half-sides and passages of {@code gap}. */
    void clear(double halfW, double halfD, double gap) {
        this.halfW = halfW;
        this.halfD = halfD;
        this.gap = gap;
        placed.clear();
        free.clear();
    }

    double halfW() {
        return halfW;
    }

    double halfD() {
        return halfD;
    }

    /** The narrowest passage kept between objects, metres. */
    double gap() {
        return gap;
    }

    /** Puts an object's footprint on the floor: later objects keep their clearance from it. */
    void place(Footprint f) {
        placed.add(f);
    }

    /** Keeps the circle around (x, z) of radius r clear of obstacles placed later. */
    void keepFree(double x, double z, double r) {
        free.add(new double[] {x, z, r});
    }

    /** A corner or a place along a wall for an area of radius r, far from {@code other}. */
    double[] landmark(double r, double[] other) {
        double inset = r + 0.02;
        for (int attempt = 0; attempt < 200; attempt++) {
            double x, z;
            int wall = random.nextInt(4);
            boolean corner = random.nextBoolean();
            double along = corner ? (random.nextBoolean() ? 1 : -1) : uniform(-0.8, 0.8);
            switch (wall) {
                case 0 -> { x = halfW - inset; z = along * (halfD - inset); }
                case 1 -> { x = -(halfW - inset); z = along * (halfD - inset); }
                case 2 -> { z = halfD - inset; x = along * (halfW - inset); }
                default -> { z = -(halfD - inset); x = along * (halfW - inset); }
            }
            x = round3(x);
            z = round3(z);
            if (other == null || Math.hypot(x - other[0], z - other[1]) >= 0.5) {
                return new double[] {x, z};
            }
        }
        throw new IllegalStateException("no room for a landmark (a bug: arenas are at least 1 m a side)");
    }

    /** A free place for an area anywhere on the floor (half the time at a wall or in a corner), far from {@code other}. */
    double[] anywhere(double r, double[] other) {
        for (int attempt = 0; attempt < 200; attempt++) {
            double[] p = random.nextBoolean() ? landmark(r, other) : spot(r, gap, 0.0);
            if (p != null && isClear(Footprint.circle(p[0], p[1], r + gap), Footprint.circle(p[0], p[1], r))
                    && (other == null || Math.hypot(p[0] - other[0], p[1] - other[1]) >= 0.5)) {
                return p;
            }
        }
        return null;
    }

    /** A random free centre for a circle of radius r keeping {@code clearance} from the walls and every object. */
    double[] spot(double r, double clearance, double extra) {
        for (int attempt = 0; attempt < 500; attempt++) {
            double m = r + clearance + extra;
            double x = round3(uniform(-halfW + m, halfW - m));
            double z = round3(uniform(-halfD + m, halfD - m));
            Footprint grown = Footprint.circle(x, z, r + clearance);
            if (isClear(grown, Footprint.circle(x, z, r))) {
                return new double[] {x, z};
            }
        }
        return null;
    }

    /** A free place for a box of {@code box}'s size (x, z, sx, sz, heading), placed there (for a "move" fault). */
    double[] spotForBox(double[] box) {
        for (int attempt = 0; attempt < 200; attempt++) {
            double x = round3(uniform(-halfW + gap + 0.06, halfW - gap - 0.06));
            double z = round3(uniform(-halfD + gap + 0.06, halfD - gap - 0.06));
            Footprint grown = Footprint.rectangle(x, z, box[2] + 2 * gap, box[3] + 2 * gap, box[4]);
            Footprint body = Footprint.rectangle(x, z, box[2], box[3], box[4]);
            if (grown.inside(halfW, halfD) && isClear(grown, body)) {
                placed.add(body);
                return new double[] {x, z};
            }
        }
        return null;
    }

    /** Whether {@code grown} (the new object with its clearance) overlaps no placed object and {@code body} no kept-free circle. */
    boolean isClear(Footprint grown, Footprint body) {
        for (Footprint p : placed) {
            if (p.overlaps(grown)) {
                return false;
            }
        }
        for (double[] c : free) {
            if (body.overlaps(Footprint.circle(c[0], c[1], c[2]))) {
                return false;
            }
        }
        return true;
    }

    /** A uniform draw in [lo, hi), or lo when the range is empty. */
    double uniform(double lo, double hi) {
        return lo >= hi ? lo : random.nextDouble(lo, hi);
    }

    static double round2(double v) {
        return Math.round(v * 100) / 100.0;
    }

    static double round3(double v) {
        return Math.round(v * 1000) / 1000.0;
    }

    /** A number as the world file writes it: an integer without decimals, else at most three. */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e9) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
    }
}
