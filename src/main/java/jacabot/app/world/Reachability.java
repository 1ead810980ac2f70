package jacabot.app.world;

import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.Footprint;
import jacabot.sim.world.WorldSpec;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.PriorityQueue;
import java.util.function.IntPredicate;

/**
 * Where a robot's centre can go from its start, and how far it has to drive: a grid of
 * {@link #STEP} m over the arena, a point free when a disc of the robot's radius (plus
 * {@link #MARGIN}) there overlaps no wall, box or inner wall, and reachable when a chain of free
 * neighbours joins it to the start. Cylinders do not block (the robot pushes them); boxes are
 * taken where they stand at start.
 *
 * <p>The generator uses it to place cylinders, the storage area and the charger only where the
 * robot can get (behind a doorway narrower than the robot there is nothing to fetch), and the
 * success criteria to judge against what the robot could physically do: how many coverage cells it
 * can enter at all, and the shortest paths of a delivery tour ({@link #from}).
 */
public final class Reachability {
    /** The grid's step, metres: fine enough to pass a 12 cm doorway with a 9 cm robot. */
    public static final double STEP = 0.01;
    /** Kept between the robot's body and any obstacle, metres. */
    public static final double MARGIN = 0.005;

    private final double halfW, halfD;
    private final int nx, nz;
    private final boolean[] free;
    private final double[] fromStart;

    private Reachability(double halfW, double halfD, boolean[] free, int nx, int nz, int start) {
        this.halfW = halfW;
        this.halfD = halfD;
        this.nx = nx;
        this.nz = nz;
        this.free = free;
        this.fromStart = start < 0 ? filled(nx * nz) : paths(start);
    }

    /** A rectangular obstacle: centre, full sizes along its own axes, heading in degrees. */
    public record Block(double x, double z, double sizeX, double sizeZ, double heading) {
        Footprint footprint() {
            return Footprint.rectangle(x, z, sizeX, sizeZ, heading);
        }

        double boundingRadius() {
            return Math.hypot(sizeX, sizeZ) / 2;
        }
    }

    /** {@return where a robot of {@code radius} starting at (x, z) can go in {@code world}} */
    public static Reachability of(WorldSpec world, double radius, double x, double z) {
        List<BoxSpec> boxes = new ArrayList<>(world.walls());
        boxes.addAll(world.boxes());
        return of(world.arena().halfWidth(), world.arena().halfDepth(), blocks(boxes), radius, x, z);
    }

    /** {@return where a robot of {@code radius} starting at (x, z) can go among these obstacles} */
    public static Reachability of(double halfW, double halfD, List<Block> obstacles, double radius, double x, double z) {
        int nx = Math.max(1, (int) Math.floor(2 * halfW / STEP));
        int nz = Math.max(1, (int) Math.floor(2 * halfD / STEP));
        boolean[] free = new boolean[nx * nz];
        double body = radius + MARGIN;
        for (int i = 0; i < nx; i++) {
            for (int k = 0; k < nz; k++) {
                double px = -halfW + (i + 0.5) * STEP, pz = -halfD + (k + 0.5) * STEP;
                free[i * nz + k] = Math.abs(px) <= halfW - body && Math.abs(pz) <= halfD - body;
            }
        }
        for (Block b : obstacles) {
            Footprint f = b.footprint();
            double reach = b.boundingRadius() + body;
            int i0 = Math.max(0, (int) Math.floor((b.x() - reach + halfW) / STEP));
            int i1 = Math.min(nx - 1, (int) Math.ceil((b.x() + reach + halfW) / STEP));
            int k0 = Math.max(0, (int) Math.floor((b.z() - reach + halfD) / STEP));
            int k1 = Math.min(nz - 1, (int) Math.ceil((b.z() + reach + halfD) / STEP));
            for (int i = i0; i <= i1; i++) {
                for (int k = k0; k <= k1; k++) {
                    int c = i * nz + k;
                    if (free[c] && f.overlaps(Footprint.circle(-halfW + (i + 0.5) * STEP, -halfD + (k + 0.5) * STEP, body))) {
                        free[c] = false;
                    }
                }
            }
        }
        Reachability probe = new Reachability(halfW, halfD, free, nx, nz, -1);
        return new Reachability(halfW, halfD, free, nx, nz, probe.nearestFree(x, z, body));
    }

    /** {@return the blocks of boxes (walls and obstacles)} */
    public static List<Block> blocks(List<BoxSpec> boxes) {
        List<Block> out = new ArrayList<>();
        for (BoxSpec b : boxes) {
            out.add(new Block(b.x(), b.z(), b.sizeX(), b.sizeZ(), b.heading()));
        }
        return out;
    }

    /** {@return whether the robot's centre can get to within {@code within} m of (x, z)} */
    public boolean canReach(double x, double z, double within) {
        return distanceTo(x, z, within) < Double.POSITIVE_INFINITY;
    }

    /** {@return the shortest drive of the robot's centre from its start to within {@code within} m of (x, z), or infinity} */
    public double distanceTo(double x, double z, double within) {
        return nearest(fromStart, x, z, within);
    }

    /**
     * {@return shortest drives from (x, z) (a point the robot can reach) instead of from the start}:
     * a delivery tour's legs from the storage area.
     */
    public Reachability from(double x, double z) {
        return new Reachability(halfW, halfD, free, nx, nz, nearestReachable(x, z));
    }

    /**
     * {@return how many cells of a coverage grid of {@code cell} m (as the run recorder lays it:
     * round(width / cell) × round(depth / cell) from the arena's corner) hold a point the robot's
     * centre can reach}
     */
    public int reachableCells(double cell) {
        int cx = Math.max(1, (int) Math.round(2 * halfW / cell)), cz = Math.max(1, (int) Math.round(2 * halfD / cell));
        boolean[] hit = new boolean[cx * cz];
        int count = 0;
        for (int i = 0; i < nx; i++) {
            for (int k = 0; k < nz; k++) {
                if (fromStart[i * nz + k] < Double.POSITIVE_INFINITY) {
                    int gx = Math.min(cx - 1, (int) Math.floor((i + 0.5) * STEP / cell));
                    int gz = Math.min(cz - 1, (int) Math.floor((k + 0.5) * STEP / cell));
                    if (!hit[gx * cz + gz]) {
                        hit[gx * cz + gz] = true;
                        count++;
                    }
                }
            }
        }
        return count;
    }

    /** {@return the share of the arena's grid points the robot's centre can reach, 0..1} */
    public double reachableShare() {
        long n = Arrays.stream(fromStart).filter(d -> d < Double.POSITIVE_INFINITY).count();
        return (double) n / fromStart.length;
    }

    private double nearest(double[] dist, double x, double z, double within) {
        double best = Double.POSITIVE_INFINITY;
        int r = (int) Math.ceil(within / STEP) + 1;
        int ci = (int) Math.floor((x + halfW) / STEP), ck = (int) Math.floor((z + halfD) / STEP);
        for (int i = Math.max(0, ci - r); i <= Math.min(nx - 1, ci + r); i++) {
            for (int k = Math.max(0, ck - r); k <= Math.min(nz - 1, ck + r); k++) {
                double px = -halfW + (i + 0.5) * STEP, pz = -halfD + (k + 0.5) * STEP;
                if (Math.hypot(px - x, pz - z) <= within + STEP / 2) {
                    best = Math.min(best, dist[i * nz + k]);
                }
            }
        }
        return best;
    }

    private int nearestFree(double x, double z, double within) {
        return nearestWhere(x, z, within, c -> free[c]);
    }

    private int nearestReachable(double x, double z) {
        return nearestWhere(x, z, 0.1, c -> fromStart[c] < Double.POSITIVE_INFINITY);
    }

    private int nearestWhere(double x, double z, double within, IntPredicate ok) {
        int r = (int) Math.ceil(within / STEP) + 1;
        int ci = (int) Math.floor((x + halfW) / STEP), ck = (int) Math.floor((z + halfD) / STEP);
        int best = -1;
        double bestD = Double.POSITIVE_INFINITY;
        for (int i = Math.max(0, ci - r); i <= Math.min(nx - 1, ci + r); i++) {
            for (int k = Math.max(0, ck - r); k <= Math.min(nz - 1, ck + r); k++) {
                double d = Math.hypot(-halfW + (i + 0.5) * STEP - x, -halfD + (k + 0.5) * STEP - z);
                if (d < bestD && ok.test(i * nz + k)) {
                    bestD = d;
                    best = i * nz + k;
                }
            }
        }
        return best;
    }

    /** Dijkstra over 8 neighbours (no corner cutting): path lengths in metres from cell {@code start}. */
    private double[] paths(int start) {
        double[] dist = filled(nx * nz);
        dist[start] = 0;
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        queue.add(new double[] {0, start});
        double diagonal = Math.sqrt(2) * STEP;
        while (!queue.isEmpty()) {
            double[] top = queue.poll();
            int c = (int) top[1];
            if (top[0] > dist[c]) {
                continue;
            }
            int i = c / nz, k = c % nz;
            for (int di = -1; di <= 1; di++) {
                for (int dk = -1; dk <= 1; dk++) {
                    int ni = i + di, nk = k + dk;
                    if ((di == 0 && dk == 0) || ni < 0 || nk < 0 || ni >= nx || nk >= nz || !free[ni * nz + nk]) {
                        continue;
                    }
                    if (di != 0 && dk != 0 && (!free[ni * nz + k] || !free[i * nz + nk])) {
                        continue;
                    }
                    double d = dist[c] + (di != 0 && dk != 0 ? diagonal : STEP);
                    if (d < dist[ni * nz + nk]) {
                        dist[ni * nz + nk] = d;
                        queue.add(new double[] {d, ni * nz + nk});
                    }
                }
            }
        }
        return dist;
    }

    private static double[] filled(int n) {
        double[] d = new double[n];
        Arrays.fill(d, Double.POSITIVE_INFINITY);
        return d;
    }
}
