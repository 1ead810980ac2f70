package jacabot.experiments;

import jacabot.experiments.geom.Segments;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;

/**
 * The way the robot has come (not in the thesis): its GPS positions, a point every {@value #STEP} m
 * driven. Every stretch between two points was driven, so a way through them is a way that exists:
 * through the doorway of a wall the robot went round, where the distance sensors (6 cm) never show
 * the doorway from afar. The points form a graph: each point is joined to the next, and to every
 * point within {@value #JOIN} m (the robot passed there again), so the way back cuts the loops of
 * the way out. {@link #waypoint} gives the point to head for along the shortest way through the
 * graph from the point nearest the robot to the point nearest the target.
 * Coordinates are the GPS's (x, z).
 */
final class Trail {
    /** Metres driven between two points kept. */
    static final double STEP = 0.04;
    /** Points this near are one place (the robot passed there again), metres. */
    static final double JOIN = 0.06;
    /** The trail must have passed this near the robot and the target to give a way, metres. */
    static final double REACH = 0.2;
    /** How far along the way the point to head for lies, metres of path. */
    static final double AHEAD = 0.25;
    /** How far the straight way to the point headed for may pass from the trail's points before it, metres. */
    static final double BEND = 0.025;

    private final List<double[]> points = new ArrayList<>();
    /**
     * The last {@link #towards} answer, for its goal point and the trail's length then: the trail
     * grows a point every {@value #STEP} m and its goal point rarely changes, while the agent asks
     * for a waypoint at every control step. Points are only ever added, so the same goal and
     * length are the same graph.
     */
    private int towardsGoal = -1, towardsSize = -1;
    private int[] towardsNext;
    private double[] towardsCost;

    /** The robot stands at (x, z): a new point once it is {@value #STEP} m from the last. */
    void at(double x, double z) {
        if (points.isEmpty() || distance(points.get(points.size() - 1), x, z) >= STEP) {
            points.add(new double[] {x, z});
        }
    }

    /**
     * {@return the point to head for, {x, z}, on the way the robot has come from (x, z) to (tx, tz),
     * or null when the trail has not passed within {@value #REACH} m of both} The target itself once
     * the way's end lies within {@value #AHEAD} m of path; before a bend, the last point before it.
     */
    double[] waypoint(double x, double z, double tx, double tz) {
        int goal = nearest(tx, tz, REACH), start = nearest(x, z, REACH);
        if (goal < 0 || start < 0) {
            return null;
        }
        if (goal != towardsGoal || points.size() != towardsSize) {
            towardsCost = new double[points.size()];
            towardsNext = towards(goal, towardsCost);
            towardsGoal = goal;
            towardsSize = points.size();
        }
        double[] toGoal = towardsCost;
        int[] next = towardsNext;
        if (Double.isInfinite(toGoal[start])) {
            return null;
        }
        List<Integer> way = new ArrayList<>();
        for (int c = start; c != goal; c = next[c]) {
            way.add(next[c]);
        }
        // the farthest point within AHEAD m of path whose chord from the robot keeps within BEND of the
        // points passed on the way (round a box's corner the chord would cut into the box)
        double walked = 0;
        double[] last = points.get(start), best = null;
        List<double[]> passed = new ArrayList<>();
        for (int c : way) {
            double[] p = points.get(c);
            walked += distance(last, p[0], p[1]);
            if (walked > AHEAD || !chordKeepsTo(x, z, p, passed)) {
                return best != null ? best.clone() : p.clone();
            }
            best = p;
            passed.add(p);
            last = p;
        }
        return new double[] {tx, tz};
    }

    /** Whether every point passed lies within {@value #BEND} m of the chord from (x, z) to {@code p}. */
    private static boolean chordKeepsTo(double x, double z, double[] p, List<double[]> passed) {
        for (double[] q : passed) {
            if (Segments.toSegment(q[0], q[1], x, z, p[0], p[1]) > BEND) {
                return false;
            }
        }
        return true;
    }

    /** The index of the point nearest (x, z) within {@code reach} m, or -1. */
    private int nearest(double x, double z, double reach) {
        int best = -1;
        double bestD = reach;
        for (int i = 0; i < points.size(); i++) {
            double d = distance(points.get(i), x, z);
            if (d <= bestD) {
                best = i;
                bestD = d;
            }
        }
        return best;
    }

    /**
     * Dijkstra from {@code goal} over the whole trail: fills {@code toGoal} with each point's way left
     * (infinite: not joined) and {@return each point's next point on its shortest way to the goal}
     */
    private int[] towards(int goal, double[] toGoal) {
        int n = points.size();
        Map<Long, List<Integer>> cells = new HashMap<>();
        for (int i = 0; i < n; i++) {
            cells.computeIfAbsent(key(points.get(i)), k -> new ArrayList<>()).add(i);
        }
        Arrays.fill(toGoal, Double.POSITIVE_INFINITY);
        int[] next = new int[n];
        Arrays.fill(next, -1);
        boolean[] done = new boolean[n];
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        toGoal[goal] = 0;
        open.add(new double[] {0, goal});
        while (!open.isEmpty()) {
            int c = (int) open.poll()[1];
            if (done[c]) {
                continue;
            }
            done[c] = true;
            double[] p = points.get(c);
            for (int k : neighbours(c, p, cells)) {
                double g = toGoal[c] + Math.hypot(points.get(k)[0] - p[0], points.get(k)[1] - p[1]);
                if (!done[k] && g < toGoal[k]) {
                    toGoal[k] = g;
                    next[k] = c;
                    open.add(new double[] {g, k});
                }
            }
        }
        return next;
    }

    /** The points joined to point {@code c}: the one before, the one after, and every point within {@value #JOIN} m. */
    private List<Integer> neighbours(int c, double[] p, Map<Long, List<Integer>> cells) {
        List<Integer> out = new ArrayList<>();
        if (c > 0) {
            out.add(c - 1);
        }
        if (c + 1 < points.size()) {
            out.add(c + 1);
        }
        long i = Math.round(Math.floor(p[0] / JOIN)), j = Math.round(Math.floor(p[1] / JOIN));
        for (long di = -1; di <= 1; di++) {
            for (long dj = -1; dj <= 1; dj++) {
                for (int k : cells.getOrDefault(pack(i + di, j + dj), List.of())) {
                    if (k != c && distance(points.get(k), p[0], p[1]) <= JOIN) {
                        out.add(k);
                    }
                }
            }
        }
        return out;
    }

    private static long key(double[] p) {
        return pack(Math.round(Math.floor(p[0] / JOIN)), Math.round(Math.floor(p[1] / JOIN)));
    }

    /**
     * One number per cell, spread by an odd multiplier (one to one): {@code Long.hashCode} of the
     * plain packing is {@code i ^ j}, so the cells of an arena fell into a few of the map's bins.
     */
    private static long pack(long i, long j) {
        return ((i << 32) ^ (j & 0xffffffffL)) * 0x9E3779B97F4A7C15L;
    }

    private static double distance(double[] p, double x, double z) {
        return Math.hypot(p[0] - x, p[1] - z);
    }
}
