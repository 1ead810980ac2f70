package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import jacabot.cartago.Artifact;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;
import jacabot.cartago.OpFeedbackParam;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What a team has searched (thesis Chapter 6, coordination among robots; not in the thesis): the
 * arena's floor as a grid of cells, each marked once a robot's camera has looked over it, and every
 * searching robot's next search point, an unseen cell away from the other robots' points. Robots
 * that each swept the arena's lanes from the same corner searched the same places (held-out team
 * worlds: four robots 2.3 times, two 1.3 times what one robot delivers); with the map each goes
 * where nobody has looked.
 *
 * <p>A look is the camera's view from a place and a heading: the cells whose centres lie within
 * {@link #VIEW_RANGE} ahead and {@link #VIEW_HALF_ANGLE} either side, and those round the robot
 * (boxes hide nothing here: the map is a guide, not a proof). Once every cell is seen the search
 * begins again, the map cleared (a cylinder knocked or hidden may lie where one looked).
 *
 * <p>A cylinder sighted by a robot that could not go for it (on its way to the charger) is a
 * <em>spot</em>: a search point before every unseen cell, done once a robot has looked at it from
 * near (far sight takes the cylinder if it is there) or given it up.
 *
 * <p>Observable property: {@code searchPoint(Agent, X, Z)}, one per searching robot, moved on as
 * soon as that cell is seen (by anyone) or that spot is done. Operations:
 * {@code searchArea(W, D, Sx, Sz, Clear)} (the arena, W by D round the origin, and the storage
 * area, a disc never searched; the first call sets them, later ones are ignored),
 * {@code spotted(X, Z)}, {@code looked(X, Z, Heading, Searching)} (marks the view; a robot not
 * searching has no search point), {@code searchFrom(X, Z, ?Px, ?Pz)} (the caller's last search
 * point is done, seen or given up; gives the next: the nearest spot no other robot goes to, else
 * the nearest unseen cell at least {@link #SPREAD} from every other robot's point, or the nearest
 * unseen if none is). Every operation is one artifact step, so two robots never get one spot, and
 * one cell only when every unseen cell lies within {@link #SPREAD} of another's point. An agent
 * that leaves loses its point.
 */
public class SearchMap extends Artifact {
    /** A cell's side, metres: half the sweep's lanes' spacing. */
    static final double CELL = 0.25;
    /** How far ahead a look marks the floor seen, metres: the camera shows a cylinder up to about 1.5 m, reliably nearer. */
    static final double VIEW_RANGE = 0.9;
    /** Half the camera's field, degrees. */
    static final double VIEW_HALF_ANGLE = 25;
    /** The floor round a robot that a look marks, metres. */
    static final double AROUND = 0.2;
    /** A cell whose centre is nearer a wall than this is not searched (a last column past the arena's side), metres. */
    static final double WALL = 0.1;
    /** Two sightings this near are one cylinder, metres. */
    static final double SAME_SPOT = 0.3;
    /** A spot looked at from this near is done (far sight takes its cylinder if it is there), metres. */
    static final double SPOT_VIEW = 0.5;
    /** Two robots' search points at least this far apart when the map allows, metres. */
    static final double SPREAD = 0.8;

    private double width;
    private double depth;
    private int nx;
    private int nz;
    /** Cells never searched (the storage area) are seen from the start. */
    private boolean[] never;
    private boolean[] seen;
    private int unseen;
    /** Cylinders sighted by robots that could not go for them (x, z), oldest first. */
    private final List<double[]> spots = new ArrayList<>();
    private final Map<AgentId, ObsProperty> points = new LinkedHashMap<>();
    private final Map<AgentId, double[]> places = new LinkedHashMap<>();

    void init() {
    }

    /** Sets the arena (W by D metres round the origin) and the storage area not to search; once. */
    @OPERATION
    void searchArea(double w, double d, double sx, double sz, double clear) {
        if (seen != null) {
            return;
        }
        if (!(w > 0 && d > 0)) {
            failed("an arena's sides must be positive, got " + w + " by " + d, "bad_arena", w, d);
        }
        width = w;
        depth = d;
        nx = Math.max(1, (int) Math.ceil(w / CELL));
        nz = Math.max(1, (int) Math.ceil(d / CELL));
        never = new boolean[nx * nz];
        for (int i = 0; i < never.length; i++) {
            double dx = cx(i) - sx, dz = cz(i) - sz;
            never[i] = dx * dx + dz * dz < clear * clear
                    || Math.abs(cx(i)) > w / 2 - WALL || Math.abs(cz(i)) > d / 2 - WALL;
        }
        clear();
    }

    /** The caller's robot looked from (x, z) facing {@code heading} degrees; not searching, it has no search point. */
    @OPERATION
    void looked(double x, double z, double heading, boolean searching) {
        if (seen == null) {
            return;
        }
        AgentId me = getCurrentOpAgentId();
        places.put(me, new double[] {x, z});
        if (!searching) {
            dropPoint(me);
        }
        double h = Math.toRadians(heading), cos = Math.cos(Math.toRadians(VIEW_HALF_ANGLE));
        double hx = Math.cos(h), hz = Math.sin(h);
        boolean marked = false;
        for (int i = 0; i < seen.length; i++) {
            if (!seen[i] && inView(cx(i) - x, cz(i) - z, VIEW_RANGE, hx, hz, cos)) {
                markSeen(i);
                marked = true;
            }
        }
        for (double[] s : List.copyOf(spots)) {
            if (inView(s[0] - x, s[1] - z, SPOT_VIEW, hx, hz, cos)) {
                spots.remove(s);
                marked = true;
            }
        }
        if (marked) {
            movePointsSeen();
        }
    }

    /**
     * A cylinder sighted at (x, z) by a robot that did not go for it (on its way to the charger): a
     * search point before any unseen cell, until a robot looks at it from near (or it is given up).
     */
    @OPERATION
    void spotted(double x, double z) {
        if (seen == null) {
            return;
        }
        double fx = Math.max(WALL - width / 2, Math.min(width / 2 - WALL, x));
        double fz = Math.max(WALL - depth / 2, Math.min(depth / 2 - WALL, z));
        for (double[] s : spots) {
            if (Math.hypot(s[0] - fx, s[1] - fz) < SAME_SPOT) {
                return;
            }
        }
        spots.add(new double[] {fx, fz});
    }

    /** The caller's last search point is done; gives it the next (the map begun again when all is seen). */
    @OPERATION
    void searchFrom(double x, double z, OpFeedbackParam<Double> px, OpFeedbackParam<Double> pz) {
        if (seen == null) {
            failed("the search map has no arena yet (searchArea)", "no_arena");
        }
        AgentId me = getCurrentOpAgentId();
        places.put(me, new double[] {x, z});
        ObsProperty old = points.get(me);
        if (old != null) {
            double[] spot = spotAt(old.doubleValue(1), old.doubleValue(2));
            if (spot != null) {
                spots.remove(spot);
            } else {
                markSeen(cell(old.doubleValue(1), old.doubleValue(2)));
            }
        }
        double[] next = pointFor(me, x, z);
        setPoint(me, next);
        px.set(next[0]);
        pz.set(next[1]);
    }

    /** {@return how many cells are left to see; read it between two artifact steps} */
    public int unseen() {
        return unseen;
    }

    @Override
    protected void agentLeft(AgentId agent) {
        dropPoint(agent);
        places.remove(agent);
    }

    private void clear() {
        seen = never.clone();
        unseen = 0;
        for (boolean n : never) {
            unseen += n ? 0 : 1;
        }
    }

    /**
     * Whether a point (dx, dz) from the robot lies round it or in its view up to {@code range} m, the
     * robot facing (hx, hz), the view's half angle's cosine {@code cos}.
     */
    private static boolean inView(double dx, double dz, double range, double hx, double hz, double cos) {
        double dist = Math.sqrt(dx * dx + dz * dz);
        return dist < AROUND || dist < range && dx * hx + dz * hz > dist * cos;
    }

    private void markSeen(int i) {
        if (i >= 0 && !seen[i]) {
            seen[i] = true;
            unseen--;
        }
    }

    /** Every robot whose point is now seen gets the next one from where it last was. */
    private void movePointsSeen() {
        for (Map.Entry<AgentId, ObsProperty> e : points.entrySet()) {
            ObsProperty p = e.getValue();
            double px = p.doubleValue(1), pz = p.doubleValue(2);
            boolean spot = spotAt(px, pz) != null;
            if (!spot && (!isCentre(px, pz) || seen[cell(px, pz)])) {
                double[] at = places.get(e.getKey());
                setPoint(e.getKey(), pointFor(e.getKey(), at[0], at[1]));
            }
        }
    }

    /** The nearest unseen cell at least SPREAD from the others' points (else the nearest unseen); all seen, the map begins again. */
    private double[] pointFor(AgentId me, double x, double z) {
        double[] spot = null;
        double spotD = Double.MAX_VALUE;
        for (double[] s : spots) {
            double d = Math.hypot(s[0] - x, s[1] - z);
            if (d < spotD && !spotTakenElsewhere(me, s[0], s[1])) {
                spotD = d;
                spot = s;
            }
        }
        if (spot != null) {
            return spot.clone();
        }
        int i = cellFor(me, x, z);
        return new double[] {cx(i), cz(i)};
    }

    private int cellFor(AgentId me, double x, double z) {
        if (unseen == 0) {
            clear();
        }
        if (unseen == 0) {
            return cell(x, z);
        }
        int best = -1, anyBest = -1;
        double bestD = Double.MAX_VALUE, anyD = Double.MAX_VALUE;
        for (int i = 0; i < seen.length; i++) {
            if (seen[i]) {
                continue;
            }
            double dx = cx(i) - x, dz = cz(i) - z, d = dx * dx + dz * dz;
            if (d < anyD) {
                anyD = d;
                anyBest = i;
            }
            if (d < bestD && apartFromOthers(me, i)) {
                bestD = d;
                best = i;
            }
        }
        return best >= 0 ? best : anyBest;
    }

    private boolean apartFromOthers(AgentId me, int i) {
        for (Map.Entry<AgentId, ObsProperty> e : points.entrySet()) {
            if (!e.getKey().equals(me)) {
                double dx = cx(i) - e.getValue().doubleValue(1), dz = cz(i) - e.getValue().doubleValue(2);
                if (dx * dx + dz * dz < SPREAD * SPREAD) {
                    return false;
                }
            }
        }
        return true;
    }

    private void setPoint(AgentId agent, double[] at) {
        ObsProperty p = points.get(agent);
        if (p == null) {
            points.put(agent, defineObsProperty("searchPoint", agent, at[0], at[1]));
        } else if (p.doubleValue(1) != at[0] || p.doubleValue(2) != at[1]) {
            p.updateValues(agent, at[0], at[1]);
        }
    }

    private double[] spotAt(double x, double z) {
        for (double[] s : spots) {
            if (s[0] == x && s[1] == z) {
                return s;
            }
        }
        return null;
    }

    /** Another agent's point is that spot already. */
    private boolean spotTakenElsewhere(AgentId me, double x, double z) {
        for (Map.Entry<AgentId, ObsProperty> e : points.entrySet()) {
            if (!e.getKey().equals(me) && e.getValue().doubleValue(1) == x && e.getValue().doubleValue(2) == z) {
                return true;
            }
        }
        return false;
    }

    private boolean isCentre(double x, double z) {
        int i = cell(x, z);
        return cx(i) == x && cz(i) == z;
    }

    private void dropPoint(AgentId agent) {
        if (points.remove(agent) != null) {
            removeObsPropertyByTemplate("searchPoint", agent, null, null);
        }
    }

    private int cell(double x, double z) {
        int i = (int) Math.floor((x + width / 2) / CELL), k = (int) Math.floor((z + depth / 2) / CELL);
        return Math.min(nx - 1, Math.max(0, i)) * nz + Math.min(nz - 1, Math.max(0, k));
    }

    private double cx(int i) {
        return -width / 2 + (i / nz + 0.5) * CELL;
    }

    private double cz(int i) {
        return -depth / 2 + (i % nz + 0.5) * CELL;
    }
}
