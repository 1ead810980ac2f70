package jacabot.experiments;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.Collections;
import java.util.List;

/**
 * The way to a target point through a map the robot makes itself (not in the thesis: its robots
 * head for a point by the compass and go round what they meet). The arena is a grid of
 * {@value #CELL} m cells. A cell where a distance sensor saw an obstacle is blocked until
 * {@code memoryMs} after its last sighting, or until the robot's centre stands in it (boxes move);
 * cells within the robot's clearance of a blocked cell or of the arena's boundary cost more to
 * cross; cells never seen are free (the robot learns a wall by meeting it). A* over the grid gives
 * the route; the robot heads for the farthest cell of the route's first {@value #LOOKAHEAD} m it can
 * reach in a straight line over free cells, and for the target itself when the straight way is free
 * or no route is known.
 * Coordinates are the GPS's (x, z), the arena centred on 0.
 */
final class RouteMap {
    static final double CELL = 0.025;
    /** The extra cost of crossing a cell within the clearance of an obstacle, in cells of path. */
    static final double NEAR_COST = 20;
    /**
     * Beside an obstacle: within this many clearances of it a cell costs {@link #BESIDE_COST} more, and the
     * point to head for is not taken there (the robot, beside a wall it follows, heads along the route's
     * next cells, not for the place past the wall's end seen where the route turns through the part of
     * the wall not seen yet: it turned into the wall at every plan).
     */
    static final double BESIDE = 1.6, BESIDE_COST = 0.5;
    /**
     * How far along a route that bends the point to head for may lie, metres: the robot keeps to the route
     * round an obstacle's end it has seen, along the obstacle, where heading for a point beyond the end cut
     * the corner into the part of the obstacle not seen yet.
     */
    static final double LOOKAHEAD = 0.2;
    /**
     * A straight run of this many blocked cells along x or z (20 cm: a box is at most 12 cm) is taken for a
     * wall's face, when the map guesses walls on ({@link #guessWalls}).
     */
    static final int FACE_RUN = 8;

    /**
     * With a firm guess ({@link #guessWallsFirm}): crossing the guessed face within its firm part, next to the
     * seen end, costs this a cell (four cells within the clearance), so a route along a face crosses past the
     * firm part, not just past the end the robot has seen (where it turned into the wall at every plan and
     * crept along it at 1-2 cm/s); and a cell within the clearance of a guessed cell costs
     * {@link #GUESS_BESIDE_COST}, so the route runs along the guess at the robot's distance from the seen face.
     */
    static final double FIRM_COST = 4 * NEAR_COST;
    static final double GUESS_BESIDE_COST = 2;
    /**
     * With a firm guess: a guess ended within this many metres of the face's seen end by an obstacle seen, a
     * cell the robot drove through or one a side sensor saw open is a gap between two things, perhaps a
     * doorway, and has no firm part (the route may cross it at once).
     */
    static final double GAP = 0.4;
    private final int cols, rows;
    private final double halfW, halfD, clearance;
    private final long memoryMs;
    /** Per cell: the simulated time of the last sighting of an obstacle there, or {@link #NEVER}. */
    private final long[] seenAt;
    private static final long NEVER = Long.MIN_VALUE;
    /** The route of the last plan, cell centres from the robot to the target (for the inspector and tests). */
    private List<double[]> lastRoute = List.of();
    /** Per cell, the extra cost of the arena's boundary alone ({@link #nearCosts} without obstacles): made once. */
    private final double[] boundaryCosts;
    /** The cells {@link #nearCosts} raises round an obstacle: {di, dj, cost} within {@link #BESIDE} clearances, made once. */
    private final double[][] around;
    /**
     * The last call's blocked cells, extra costs, and plan: the map changes far less often than the
     * agent asks for a waypoint (every control step while it heads for a point), and the costs and
     * the plan are functions of the blocked cells (with the start and goal cells for the plan).
     */
    private BitSet lastLive;
    private double[] lastNear;
    private int lastStart = -1, lastGoal = -1;
    private List<Integer> lastPlan;
    /** Per cell: whether the robot's centre has stood there (a doorway it drove through is open). */
    private final BitSet driven;
    /** Per cell: whether a side sensor's ray passed there without an obstacle ({@link #seenFree}); with the firm guess only. */
    private final BitSet seenOpen;
    private int openCount, lastOpen = -1;
    /** The firm part of a face's guess, in cells (0: none, and no cell is taken as seen open). */
    private int firmCells;
    /** How far past a face's seen end the wall is guessed to go on, in cells (0: no guess), and the driven cells' count the costs were made with. */
    private int guessCells;
    private int lastDriven = -1;

    /**
     * @param width     the arena's side along x, metres
     * @param depth     the arena's side along z, metres
     * @param clearance how near an obstacle the robot's centre should not come, metres (its radius and a margin)
     * @param memoryMs  how long an obstacle seen once stays on the map, simulated ms
     */
    RouteMap(double width, double depth, double clearance, long memoryMs) {
        if (!(width > CELL) || !(depth > CELL) || !(clearance >= 0) || memoryMs <= 0) {
            throw new IllegalArgumentException("route map needs an arena over " + CELL + " m a side, a clearance >= 0 and a memory > 0, got "
                    + width + " x " + depth + ", " + clearance + ", " + memoryMs);
        }
        halfW = width / 2;
        halfD = depth / 2;
        cols = (int) Math.ceil(width / CELL);
        rows = (int) Math.ceil(depth / CELL);
        this.clearance = clearance;
        this.memoryMs = memoryMs;
        seenAt = new long[cols * rows];
        Arrays.fill(seenAt, NEVER);
        driven = new BitSet(cols * rows);
        seenOpen = new BitSet(cols * rows);
        double beside = BESIDE * clearance;
        boundaryCosts = new double[cols * rows];
        for (int i = 0; i < cols; i++) {
            for (int j = 0; j < rows; j++) {
                double[] p = centre(index(i, j));
                double edge = Math.min(halfW - Math.abs(p[0]), halfD - Math.abs(p[1]));
                if (edge < beside) {
                    raise(boundaryCosts, index(i, j), edge < clearance ? NEAR_COST : BESIDE_COST);
                }
            }
        }
        int r = (int) Math.ceil(beside / CELL);
        List<double[]> cells = new ArrayList<>();
        for (int di = -r; di <= r; di++) {
            for (int dj = -r; dj <= r; dj++) {
                double d = Math.hypot(di, dj) * CELL;
                if (d <= beside) {
                    cells.add(new double[] {di, dj, d <= clearance ? NEAR_COST : BESIDE_COST});
                }
            }
        }
        around = cells.toArray(new double[0][]);
    }

    /** An obstacle's surface seen at (x, z) at simulated time {@code nowMs}. */
    void obstacle(double x, double z, long nowMs) {
        int c = cell(x, z);
        if (c >= 0) {
            seenAt[c] = nowMs;
        }
    }

    /** The robot's centre stands at (x, z): nothing is there now (a box seen there has moved). */
    void standing(double x, double z) {
        int c = cell(x, z);
        if (c >= 0) {
            seenAt[c] = NEVER;
            driven.set(c);
        }
    }

    /**
     * Guess that a wall's face seen goes on for {@code metres} past its seen end, where the robot has not
     * driven (not in the thesis): crossing that line costs as much as a cell within the clearance, so a
     * route takes a doorway the robot drove through before a way round the face's unseen end (floor
     * never seen is free otherwise). 0 turns the guess off.
     */
    void guessWalls(double metres) {
        guessCells = (int) Math.round(Math.max(0, metres) / CELL);
        lastLive = null;
    }

    /**
     * Makes the guess firm for its first {@code metres} past a face's seen end (not in the thesis; 0: as
     * {@link #guessWalls} alone): see {@link #FIRM_COST}, {@link #GUESS_BESIDE_COST} and {@link #GAP}; a guess
     * also ends where a side sensor saw the floor open ({@link #seenFree}: the end of a wall the robot drives
     * along, where it turns).
     */
    void guessWallsFirm(double metres) {
        firmCells = (int) Math.round(Math.max(0, metres) / CELL);
        lastLive = null;
    }

    /** {@return whether the guess has a firm part: the middleware then reports the side sensors' open rays} */
    boolean firmGuess() {
        return guessCells > 0 && firmCells > 0;
    }

    /** A side sensor saw no obstacle along its ray from (x, z) to (tx, tz): those cells are open (a face's guess ends there). */
    void seenFree(double x, double z, double tx, double tz) {
        walk(x, z, tx, tz, (f, c) -> {
            if (c >= 0 && !seenOpen.get(c)) {
                seenOpen.set(c);
                openCount++;
            }
            return true;
        });
    }

    /** One point of a line walked by {@link #walk}: its fraction of the way (0 and 1 exactly at the ends) and its cell (-1: off the map). */
    private interface LineStep {
        /** {@return whether the walk goes on} */
        boolean at(double f, int cell);
    }

    /** Walks the line from (x, z) to (tx, tz) in half-cell steps, both ends included; {@return false when a step stopped it} */
    private boolean walk(double x, double z, double tx, double tz, LineStep step) {
        int steps = (int) Math.ceil(Math.hypot(tx - x, tz - z) / (CELL / 2));
        for (int k = 0; k <= steps; k++) {
            double f = steps == 0 ? 0 : (double) k / steps;
            if (!step.at(f, cell(x + f * (tx - x), z + f * (tz - z)))) {
                return false;
            }
        }
        return true;
    }

    /** {@return whether an obstacle is on the map at (x, z) at {@code nowMs}} */
    boolean blocked(double x, double z, long nowMs) {
        int c = cell(x, z);
        return c >= 0 && live(c, nowMs);
    }

    /** {@return the route of the last {@link #waypoint} call, cell centres {x, z} from the robot to the target (empty: the straight way)} */
    List<double[]> lastRoute() {
        return lastRoute;
    }

    /**
     * {@return the point to head for, {x, z}, from the robot at (x, z) to the target (tx, tz)}: the
     * target when the straight way is free or no route is known, else the farthest cell of the
     * route seen in a straight line.
     */
    double[] waypoint(double x, double z, double tx, double tz, long nowMs) {
        List<double[]> points = route(x, z, tx, tz, nowMs);
        lastRoute = points;
        if (points.isEmpty()) {
            return new double[] {tx, tz};
        }
        int ahead = Math.min(points.size() - 1, (int) Math.round(LOOKAHEAD / CELL));
        for (int i = ahead; i > 0; i--) {
            double[] p = points.get(i);
            if (clear(x, z, p[0], p[1], lastNear, nowMs)) {
                return p;
            }
        }
        return points.get(Math.min(1, points.size() - 1));
    }

    /**
     * {@return the route from the robot at (x, z) to the target (tx, tz), cell centres {x, z} and the target
     * last; empty when the straight way is free or no route is known}; the map's costs and the plan are kept
     * for the next call while the map and the cells stay the same
     */
    private List<double[]> route(double x, double z, double tx, double tz, long nowMs) {
        int start = cell(x, z), goal = cell(tx, tz);
        if (start < 0 || goal < 0 || start == goal) {
            return List.of();
        }
        BitSet live = live(nowMs);
        boolean sameMap = live.equals(lastLive) && (guessCells == 0 || driven.cardinality() == lastDriven && openCount == lastOpen);
        if (!sameMap) {
            lastLive = live;
            lastDriven = driven.cardinality();
            lastOpen = openCount;
            lastNear = nearCosts(live);
            lastPlan = null;
        }
        if (clear(x, z, tx, tz, lastNear, nowMs)) {
            return List.of();
        }
        if (lastPlan == null || start != lastStart || goal != lastGoal) {
            lastPlan = plan(start, goal, lastNear, nowMs);
            lastStart = start;
            lastGoal = goal;
        }
        if (lastPlan.isEmpty()) {
            return List.of();
        }
        List<double[]> points = new ArrayList<>();
        for (int c : lastPlan) {
            points.add(centre(c));
        }
        points.set(points.size() - 1, new double[] {tx, tz});
        return Collections.unmodifiableList(points);
    }

    /**
     * {@return the length, metres, of the way from (x, z) to the target (tx, tz) the map gives at {@code nowMs}}:
     * along the route {@link #route} plans (the one {@link #waypoint} heads along), or the straight distance
     * when the straight way is free or no route is known. {@link #lastRoute} stays the last {@code waypoint}
     * call's (the robot's own route).
     */
    double routeLength(double x, double z, double tx, double tz, long nowMs) {
        List<double[]> route = route(x, z, tx, tz, nowMs);
        double length = 0, px = x, pz = z;
        for (double[] p : route) {
            length += Math.hypot(p[0] - px, p[1] - pz);
            px = p[0];
            pz = p[1];
        }
        return route.isEmpty() ? Math.hypot(tx - x, tz - z) : length;
    }

    private boolean live(int c, long nowMs) {
        return seenAt[c] != NEVER && nowMs - seenAt[c] < memoryMs;
    }

    /** {@return the cells blocked at {@code nowMs}} */
    private BitSet live(long nowMs) {
        BitSet live = new BitSet(cols * rows);
        for (int c = 0; c < cols * rows; c++) {
            if (live(c, nowMs)) {
                live.set(c);
            }
        }
        return live;
    }

    /**
     * Per cell, the extra cost of crossing it: {@link #NEAR_COST} within the clearance of an obstacle or the
     * boundary, {@link #BESIDE_COST} within {@link #BESIDE} times the clearance, else 0 (the largest that
     * applies: the boundary's, made once, raised round each blocked cell).
     */
    private double[] nearCosts(BitSet live) {
        double[] near = boundaryCosts.clone();
        for (int c = live.nextSetBit(0); c >= 0; c = live.nextSetBit(c + 1)) {
            int i = c % cols, j = c / cols;
            for (double[] o : around) {
                int a = i + (int) o[0], b = j + (int) o[1];
                if (a >= 0 && b >= 0 && a < cols && b < rows) {
                    raise(near, index(a, b), o[2]);
                }
            }
        }
        if (guessCells > 0) {
            guessFaces(live, near);
        }
        return near;
    }

    /**
     * Raises the cells past each face's seen end, along it, by {@link #NEAR_COST} ({@link #FIRM_COST} within the firm
     * part), up to {@link #guessCells} or a driven cell (or, with the firm part, one seen open).
     */
    private void guessFaces(BitSet live, double[] near) {
        int[][] dirs = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (int c = live.nextSetBit(0); c >= 0; c = live.nextSetBit(c + 1)) {
            int i = c % cols, j = c / cols;
            for (int[] d : dirs) {
                if (band(live, i + d[0], j + d[1], d) || !faceBehind(live, i, j, d)) {
                    continue;
                }
                int run = 0;
                boolean bounded = false;
                for (int k = 1; k <= guessCells; k++) {
                    int a = i + k * d[0], b = j + k * d[1];
                    if (a < 0 || b < 0 || a >= cols || b >= rows) {
                        break;
                    }
                    if (driven.get(index(a, b)) || seenOpen.get(index(a, b)) && !live.get(index(a, b)) || band(live, a, b, d)) {
                        bounded = k * CELL <= GAP;
                        break;
                    }
                    run = k;
                }
                boolean firm = firmCells > 0 && !bounded;
                for (int k = 1; k <= run; k++) {
                    int a = i + k * d[0], b = j + k * d[1];
                    raise(near, index(a, b), firm && k <= firmCells ? FIRM_COST : NEAR_COST);
                    if (firmCells > 0) {
                        for (double[] o : around) {
                            int e = a + (int) o[0], f = b + (int) o[1];
                            if (o[2] == NEAR_COST && e >= 0 && f >= 0 && e < cols && f < rows) {
                                raise(near, index(e, f), GUESS_BESIDE_COST);
                            }
                        }
                    }
                }
            }
        }
    }

    /** {@return whether the {@link #FACE_RUN} - 1 cells behind (i, j), against d, are blocked, each or a neighbour across d} */
    private boolean faceBehind(BitSet live, int i, int j, int[] d) {
        for (int k = 1; k < FACE_RUN; k++) {
            if (!band(live, i - k * d[0], j - k * d[1], d)) {
                return false;
            }
        }
        return true;
    }

    /** {@return whether cell (a, b) or one of its two neighbours across direction d is blocked} */
    private boolean band(BitSet live, int a, int b, int[] d) {
        for (int s = -1; s <= 1; s++) {
            int x = a + s * d[1], y = b + s * d[0];
            if (x >= 0 && y >= 0 && x < cols && y < rows && live.get(index(x, y))) {
                return true;
            }
        }
        return false;
    }

    private static void raise(double[] near, int c, double cost) {
        near[c] = Math.max(near[c], cost);
    }

    /**
     * Whether the straight way from (x, z) to (tx, tz) meets no obstacle and no cell beside one, but in
     * the robot's own cell and near the target (it may lie by a wall). Near the robot too, a point
     * just past the end of a wall seen, along it, would count as clear and the robot turn into the
     * part of the wall not seen yet, again at every step.
     */
    private boolean clear(double x, double z, double tx, double tz, double[] near, long nowMs) {
        double length = Math.hypot(tx - x, tz - z);
        return walk(x, z, tx, tz, (f, c) -> {
            if (c < 0) {
                return false;
            }
            boolean atEnd = f * length <= CELL || (1 - f) * length <= clearance + CELL;
            return !(live(c, nowMs) && !(f == 0 || f == 1) || near[c] > 0 && !atEnd);
        });
    }

    /**
     * A* over the 8-connected grid; blocked cells are walls, a diagonal step does not cut a blocked corner.
     * Its arrays are kept from plan to plan and its queue holds primitives ({@link CellQueue}), with
     * {@link java.util.PriorityQueue}'s order among equal costs, so the routes are the ones a
     * {@code PriorityQueue} of boxed entries gave (it was 7 % of the agent's thread in experiment 4).
     */
    private List<Integer> plan(int start, int goal, double[] near, long nowMs) {
        int n = cols * rows;
        if (cost == null) {
            cost = new double[n];
            from = new int[n];
            done = new boolean[n];
            open = new CellQueue();
        }
        Arrays.fill(cost, Double.POSITIVE_INFINITY);
        Arrays.fill(from, -1);
        Arrays.fill(done, false);
        open.clear();
        cost[start] = 0;
        open.add(heuristic(start, goal), start);
        while (!open.isEmpty()) {
            int c = open.poll();
            if (done[c]) {
                continue;
            }
            if (c == goal) {
                return trace(from, start, goal);
            }
            done[c] = true;
            int ci = c % cols, cj = c / cols;
            for (int di = -1; di <= 1; di++) {
                for (int dj = -1; dj <= 1; dj++) {
                    int a = ci + di, b = cj + dj;
                    if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= cols || b >= rows) {
                        continue;
                    }
                    int next = index(a, b);
                    if (done[next] || (next != goal && live(next, nowMs))) {
                        continue;
                    }
                    if (di != 0 && dj != 0 && (live(index(ci + di, cj), nowMs) || live(index(ci, cj + dj), nowMs))) {
                        continue;
                    }
                    double g = cost[c] + (di != 0 && dj != 0 ? Math.sqrt(2) : 1) + near[next];
                    if (g < cost[next]) {
                        cost[next] = g;
                        from[next] = c;
                        open.add(g + heuristic(next, goal), next);
                    }
                }
            }
        }
        return List.of();
    }

    /** {@link #plan}'s arrays, made at the first plan and filled anew at each. */
    private double[] cost;
    private int[] from;
    private boolean[] done;
    private CellQueue open;
    /** Per (|di|, |dj|), {@code Math.hypot(di, dj)}, filled as asked (0: not yet; the only true 0 is (0, 0)). */
    private double[] hypots;

    private List<Integer> trace(int[] from, int start, int goal) {
        List<Integer> route = new ArrayList<>();
        for (int c = goal; c != start; c = from[c]) {
            route.add(c);
        }
        route.add(start);
        Collections.reverse(route);
        return route;
    }

    private double heuristic(int a, int b) {
        if (hypots == null) {
            hypots = new double[cols * rows];
        }
        int k = Math.abs(a / cols - b / cols) * cols + Math.abs(a % cols - b % cols);
        double h = hypots[k];
        if (h == 0) {
            // hypot ignores the signs, so the absolute offsets give the same value
            h = Math.hypot(a % cols - b % cols, a / cols - b / cols);
            hypots[k] = h;
        }
        return h;
    }

    private int cell(double x, double z) {
        int i = (int) Math.floor((x + halfW) / CELL), j = (int) Math.floor((z + halfD) / CELL);
        return i < 0 || j < 0 || i >= cols || j >= rows ? -1 : index(i, j);
    }

    private int index(int i, int j) {
        return j * cols + i;
    }

    private double[] centre(int c) {
        return new double[] {-halfW + (c % cols + 0.5) * CELL, -halfD + (c / cols + 0.5) * CELL};
    }
}
