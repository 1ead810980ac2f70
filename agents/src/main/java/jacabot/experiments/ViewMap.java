package jacabot.experiments;

import java.util.Arrays;

/**
 * The floor the robot's camera has looked over (not in the thesis): the arena as a grid of
 * {@value #CELL} m cells, each with the nearest distance from which a look (the robot's place and
 * heading while its camera scans) had it in view, {@value #HALF_ANGLE} degrees either side up to
 * {@value #FAR} m, or round the robot within {@value #AROUND} m. A search asks for the nearest cell not
 * yet looked at from within its range (boxes hide nothing here: a shorter range is the caution), away
 * from the walls and the storage area; once every cell was looked at, the map begins again.
 * Coordinates are the GPS's (x, z), the arena centred on 0.
 */
final class ViewMap {
    static final double CELL = 0.25;
    static final double HALF_ANGLE = 25;
    static final double FAR = 1.5;
    static final double AROUND = 0.2;
    /** A cell whose centre is nearer a wall than this is not searched, metres. */
    static final double WALL = 0.1;

    private final double width, depth;
    private final int nx, nz;
    /** Per cell: the nearest a look had its centre in view, metres (infinite: never). */
    private final double[] nearest;

    ViewMap(double width, double depth) {
        this.width = width;
        this.depth = depth;
        nx = Math.max(1, (int) Math.ceil(width / CELL));
        nz = Math.max(1, (int) Math.ceil(depth / CELL));
        nearest = new double[nx * nz];
        Arrays.fill(nearest, Double.POSITIVE_INFINITY);
    }

    /** The camera looked from (x, z) facing {@code headingDeg} (the compass' orientation, degrees). */
    void looked(double x, double z, double headingDeg) {
        double h = Math.toRadians(headingDeg), hx = Math.cos(h), hz = Math.sin(h);
        double cos = Math.cos(Math.toRadians(HALF_ANGLE));
        for (int i = 0; i < nearest.length; i++) {
            double dx = cx(i) - x, dz = cz(i) - z, d = Math.sqrt(dx * dx + dz * dz);
            if (d < nearest[i] && (d < AROUND || d < FAR && dx * hx + dz * hz > d * cos)) {
                nearest[i] = d;
            }
        }
    }

    /** {@return whether the cell at (x, z) was looked at from within {@code range} m; a point off the arena counts as seen} */
    boolean seen(double x, double z, double range) {
        int i = cell(x, z);
        return i < 0 || nearest[i] <= range;
    }

    /** Marks the cell at (x, z) as looked at from where it lies (a search point given up). */
    void giveUp(double x, double z) {
        int i = cell(x, z);
        if (i >= 0) {
            nearest[i] = 0;
        }
    }

    /**
     * {@return the centre {x, z} of the nearest cell to (x, z) not looked at from within {@code range},
     * off the walls and farther than {@code clear} from (sx, sz)}; every one seen, the map begins again
     * (null: no cell can be searched)
     */
    double[] nearestUnseen(double x, double z, double range, double sx, double sz, double clear) {
        for (int round = 0; round < 2; round++) {
            int best = -1;
            double bestD = Double.MAX_VALUE;
            for (int i = 0; i < nearest.length; i++) {
                double ex = cx(i) - sx, ez = cz(i) - sz;
                boolean searchable = ex * ex + ez * ez >= clear * clear
                        && Math.abs(cx(i)) <= width / 2 - WALL && Math.abs(cz(i)) <= depth / 2 - WALL;
                double dx = cx(i) - x, dz = cz(i) - z, d = dx * dx + dz * dz;
                if (searchable && nearest[i] > range && d < bestD) {
                    bestD = d;
                    best = i;
                }
            }
            if (best >= 0) {
                return new double[] {cx(best), cz(best)};
            }
            Arrays.fill(nearest, Double.POSITIVE_INFINITY);
        }
        return null;
    }

    private int cell(double x, double z) {
        int i = (int) Math.floor((x + width / 2) / CELL), k = (int) Math.floor((z + depth / 2) / CELL);
        return i < 0 || i >= nx || k < 0 || k >= nz ? -1 : i * nz + k;
    }

    private double cx(int i) {
        return -width / 2 + (i / nz + 0.5) * CELL;
    }

    private double cz(int i) {
        return -depth / 2 + (i % nz + 0.5) * CELL;
    }
}
