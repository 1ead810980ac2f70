package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;
import jacabot.cartago.OpFeedbackParam;
import jacabot.experiments.geom.Segments;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * A team's task board (thesis Chapter 6, coordination among robots; after the claims of Jason's
 * gold-miners, kept in an artifact as JaCa would): a robot that sights a cylinder claims it by its
 * estimated place on the floor, so that no other robot goes for it, and releases the claim when it
 * gives up or completes it when the cylinder is in the storage area.
 *
 * <p>A claim is a disc: the estimated place and how far off the estimate may be (a camera's
 * estimate of a cylinder 1.4 m away was 0.45 m off, one 0.2 m away a few centimetres). Two claims
 * whose discs overlap may be one cylinder, so a claim is refused while it overlaps another agent's:
 * whichever way two robots' estimates of one cylinder err, within their bounds they overlap.
 * Claims are by place because that is what a robot perceives ({@code cylinderSighted(Offset,
 * Distance)} from where it stands); a cylinder's name is the world file's, which no robot sees.
 * A robot's claim shrinks as it comes nearer (its newer estimate, the same claim), and the
 * cylinder it carries is claimed where the robot is ({@code at}), so that nobody claims it on its
 * way to the storage area.
 *
 * <p>Observable properties: {@code claimed(Id, Agent, X, Z, R)}, one per claim (Agent an atom, R
 * the disc's radius), and {@code completed(N)}, the team's deliveries. Operations:
 * {@code claim(X, Z, R, ?Id)}, {@code claim(X, Z)} and {@code claim(X, Z, ?Id)} (R half the
 * board's radius), {@code claimAlong(X, Z, R, ToX, ToZ, ?Id)} (a sighting's disc swept on along its
 * bearing: the board tests the whole shape, the property shows the disc), {@code take(X, Z, ?Id)}, {@code putDown(X, Z)}, {@code release(Id)} and
 * {@code release(Id, Why)} (why: the agent's reason, logged),
 * {@code complete(Id)}, {@code releaseAll}. The board logs every claim made (its place and
 * radius), every release (its place and reason) and every claim voided by a take. Every operation is one artifact step: the test and
 * the claim are one, so two agents can never hold overlapping claims, however their calls
 * interleave. An agent that leaves the workspace (its process ended) loses its claims:
 * {@link #agentLeft} frees them and signals {@code claimsFreed(Agent, N)}.
 *
 * <p>The board also shows where the robots are and whose turn it is at the storage point, where
 * every delivery ends (a robot's distance sensors see another only as an obstacle, and a robot
 * putting a cylinder down does not look): {@code at(X, Z)} publishes the caller's place as
 * {@code robotAt(Agent, X, Z)}; {@code awaitStorageTurn} queues the caller for the storage area
 * and waits until it is the head, {@code storageDone} leaves that queue; {@code storageQueue(List)}
 * shows it, the robot whose turn it is first.
 */
public class TaskBoard extends Artifact {
    /** Places closer than this are one cylinder, metres. */
    static final double DEFAULT_RADIUS = 0.1;
    /**
     * The disc of a carried cylinder's claim, metres: it is where its robot last published its
     * place (about once a second, so up to a second of travel behind) and 6 cm ahead of that.
     */
    static final double CARRIED_RADIUS = 0.2;

    /**
     * A claim: the disc of radius r round the estimated place (x, z), swept on to (fx, fz) when the
     * claim is a sighting's (its far end on the sighting's bearing); the property shows the disc.
     */
    private static final class Claim {
        private final int id;
        private final AgentId agent;
        private final ObsProperty property;
        private double fx;
        private double fz;

        Claim(int id, AgentId agent, ObsProperty property) {
            this.id = id;
            this.agent = agent;
            this.property = property;
            this.fx = x();
            this.fz = z();
        }

        int id() {
            return id;
        }

        AgentId agent() {
            return agent;
        }

        double x() {
            return property.doubleValue(2);
        }

        double z() {
            return property.doubleValue(3);
        }

        double r() {
            return property.doubleValue(4);
        }

        boolean overlaps(double x, double z, double r) {
            return overlaps(x, z, x, z, r);
        }

        boolean overlaps(double x, double z, double toX, double toZ, double r) {
            return Segments.distance(x(), z(), fx, fz, x, z, toX, toZ) < r() + r;
        }

        void place(double x, double z, double r) {
            place(x, z, x, z, r);
        }

        void place(double x, double z, double toX, double toZ, double r) {
            property.updateValues(id, agent, x, z, r);
            sweepTo(toX, toZ);
        }

        /** Sweeps the disc on to (toX, toZ); the property, the disc, stays as it is. */
        void sweepTo(double toX, double toZ) {
            fx = toX;
            fz = toZ;
        }
    }

    private final Map<Integer, Claim> claims = new LinkedHashMap<>();
    /** The claims whose cylinder its robot carries: they follow the robot. */
    private final Set<Integer> carried = new HashSet<>();
    private final Map<AgentId, ObsProperty> places = new LinkedHashMap<>();
    private final TurnQueue storage = new TurnQueue();
    private double radius;
    private int lastId;

    /** A claim as a run's checks read it (no two claimers on one cylinder): the agent's name and the place. */
    public record Held(int id, String agent, double x, double z) {
    }

    void init() {
        init(DEFAULT_RADIUS);
    }

    void init(double radius) {
        if (!(radius > 0)) {
            failed("the task board's radius must be positive, got " + radius, "bad_radius", radius);
        }
        this.radius = radius;
        defineObsProperty("completed", 0);
        defineObsProperty("storageQueue", List.of());
    }

    /** Publishes where the caller's robot is: {@code robotAt(Agent, X, Z)}, one per robot. */
    @OPERATION
    void at(double x, double z) {
        AgentId me = getCurrentOpAgentId();
        ObsProperty p = places.get(me);
        if (p == null) {
            places.put(me, defineObsProperty("robotAt", me, x, z));
        } else {
            p.updateValues(me, x, z);
        }
        for (int id : carried) {
            Claim c = claims.get(id);
            if (c.agent().equals(me)) {
                c.place(x, z, CARRIED_RADIUS);
            }
        }
    }

    /**
     * Queues the caller for the storage area (joining the tail once) and waits until its turn
     * comes; fails with {@code not_queued} if it leaves the queue meanwhile.
     */
    @OPERATION
    void awaitStorageTurn() {
        AgentId me = getCurrentOpAgentId();
        if (storage.join(me)) {
            publishStorage();
        }
        await("storageTurnOrGone", me);
        if (!storage.contains(me)) {
            failed(me.name() + " left the storage area's queue while waiting", "not_queued");
        }
    }

    @GUARD
    boolean storageTurnOrGone(AgentId agent) {
        return storage.headOrGone(agent);
    }

    /** Leaves the storage area's queue (its turn, if it had it; not queued is fine). */
    @OPERATION
    void storageDone() {
        if (storage.leave(getCurrentOpAgentId())) {
            publishStorage();
        }
    }

    /** Claims the cylinder at (x, z) for the calling agent; see {@link #claim(double, double, double, OpFeedbackParam)}. */
    @OPERATION
    void claim(double x, double z) {
        claim(x, z, radius / 2, new OpFeedbackParam<>());
    }

    /** Claims the cylinder at (x, z), give or take half the board's radius; see {@link #claim(double, double, double, OpFeedbackParam)}. */
    @OPERATION
    void claim(double x, double z, OpFeedbackParam<Integer> id) {
        claim(x, z, radius / 2, id);
    }

    /**
     * Claims the cylinder estimated at (x, z), give or take r metres, for the calling agent and
     * gives the claim's id. Fails with {@code claimed_by(Agent, Id)} when the disc overlaps another
     * agent's claim. A claim of the caller's own that it overlaps (not the one of the cylinder it
     * carries) is the same claim: its id comes back and it becomes (x, z, r), the newer estimate.
     */
    @OPERATION
    void claim(double x, double z, double r, OpFeedbackParam<Integer> id) {
        claimAlong(x, z, r, x, z, id);
    }

    /**
     * Claims a cylinder sighted at the estimated place (x, z) that may lie farther on the
     * sighting's bearing, up to (toX, toZ): the claim is the disc of radius r round (x, z) swept on
     * to (toX, toZ). A camera's bearing is good and its distance is not, and a cylinder half hidden
     * seems nearer than it is (one 0.7 m away estimated at 0.39 m): two robots' estimates of one
     * such cylinder, from two sides, missed each other's discs. Otherwise as
     * {@link #claim(double, double, double, OpFeedbackParam)}, every test against the swept shape.
     */
    @OPERATION
    void claimAlong(double x, double z, double r, double toX, double toZ, OpFeedbackParam<Integer> id) {
        if (!(r > 0)) {
            failed("a claim's radius must be positive, got " + r, "bad_radius", r);
        }
        AgentId me = getCurrentOpAgentId();
        Claim mine = null;
        for (Claim c : claims.values()) {
            if (c.overlaps(x, z, toX, toZ, r)) {
                if (!c.agent().equals(me)) {
                    failed(c.agent().name() + " has claimed the cylinder at (" + c.x() + ", " + c.z() + ")",
                            "claimed_by", c.agent(), c.id());
                }
                if (mine == null && !carried.contains(c.id())) {
                    mine = c;
                }
            }
        }
        if (mine != null) {
            mine.place(x, z, toX, toZ, r);
            id.set(mine.id());
            return;
        }
        Claim made = newClaim(me, x, z, r);
        made.sweepTo(toX, toZ);
        id.set(made.id());
    }

    /**
     * The caller has picked up the cylinder at (x, z): the cylinder is its own in fact, so every
     * other agent's claim that may name it (its disc within half the board's radius of the place)
     * is void, except a claim on a cylinder another robot carries (that one is in its gripper,
     * not here: voiding it made that robot's delivery fail to complete its claim), the caller's
     * other claims are released (a robot carries one cylinder), and its
     * claim there is given back, made if need be; from now on that claim follows the robot's
     * published place ({@code at}) until {@code putDown}, with a disc of {@link #CARRIED_RADIUS}.
     */
    @OPERATION
    void take(double x, double z, OpFeedbackParam<Integer> id) {
        AgentId me = getCurrentOpAgentId();
        Claim kept = null;
        for (Claim c : List.copyOf(claims.values())) {
            boolean there = c.overlaps(x, z, radius / 2);
            if (there && c.agent().equals(me) && kept == null) {
                kept = c;
            } else if (c.agent().equals(me) || there && !carried.contains(c.id())) {
                if (!c.agent().equals(me)) {
                    log(c.agent().name() + "'s claim " + c.id() + " at " + place(c) + " void: " + me.name() + " took the cylinder");
                }
                drop(c);
            }
        }
        int taken;
        if (kept != null) {
            kept.place(x, z, CARRIED_RADIUS);
            taken = kept.id();
        } else {
            taken = newClaim(me, x, z, CARRIED_RADIUS).id();
        }
        carried.add(taken);
        id.set(taken);
    }

    /**
     * The caller has let its cylinder go at (x, z) (it fell, or it was put down): its carried claim
     * stays there, half the board's radius wide, and no longer follows the robot (none is fine).
     */
    @OPERATION
    void putDown(double x, double z) {
        AgentId me = getCurrentOpAgentId();
        for (int id : List.copyOf(carried)) {
            Claim c = claims.get(id);
            if (c.agent().equals(me)) {
                carried.remove(id);
                c.place(x, z, radius / 2);
            }
        }
    }

    /** Gives up the caller's claim {@code id}: another agent may claim that cylinder now. */
    @OPERATION
    void release(int id) {
        release(id, "no reason given");
    }

    /**
     * Gives up the caller's claim {@code id}, and logs its place and {@code why} (the agent's
     * reason, any term), so that a run's console says where each claim ended and why.
     */
    @OPERATION
    void release(int id, Object why) {
        Claim c = owned(id);
        log(c.agent().name() + " releases claim " + id + " at " + place(c) + ": " + why);
        drop(c);
    }

    /** The caller's claim {@code id} is done (its cylinder delivered): the claim goes, {@code completed} counts it. */
    @OPERATION
    void complete(int id) {
        drop(owned(id));
        ObsProperty completed = getObsProperty("completed");
        completed.updateValue(completed.intValue() + 1);
    }

    /** Gives up every claim of the caller (none is fine). */
    @OPERATION
    void releaseAll() {
        freeAll(getCurrentOpAgentId());
    }

    /** {@return the claims now, oldest first; read it between two artifact steps (a lockstep run's)} */
    public List<Held> claims() {
        List<Held> out = new ArrayList<>();
        for (Claim c : claims.values()) {
            out.add(new Held(c.id(), c.agent().name(), c.x(), c.z()));
        }
        return out;
    }

    @Override
    protected void agentLeft(AgentId agent) {
        if (storage.leave(agent)) {
            publishStorage();
        }
        if (places.remove(agent) != null) {
            removeObsPropertyByTemplate("robotAt", agent, null, null);
        }
        int freed = freeAll(agent);
        if (freed > 0) {
            signal("claimsFreed", agent, freed);
        }
    }

    private Claim newClaim(AgentId agent, double x, double z, double r) {
        int next = ++lastId;
        Claim c = new Claim(next, agent, defineObsProperty("claimed", next, agent, x, z, r));
        claims.put(next, c);
        log(agent.name() + " claims " + next + " at " + place(c) + " r " + String.format(Locale.ROOT, "%.2f", r));
        return c;
    }

    /** {@return a claim's place for the log, to the centimetre} */
    private static String place(Claim c) {
        return String.format(Locale.ROOT, "(%.2f, %.2f)", c.x(), c.z());
    }

    private void publishStorage() {
        getObsProperty("storageQueue").updateValue(storage.agents());
    }

    private Claim owned(int id) {
        Claim c = claims.get(id);
        if (c == null) {
            failed("no claim " + id + " on the task board", "no_claim", id);
        }
        if (!c.agent().equals(getCurrentOpAgentId())) {
            failed("claim " + id + " is " + c.agent().name() + "'s", "not_yours", c.agent(), id);
        }
        return c;
    }

    private int freeAll(AgentId agent) {
        List<Claim> theirs = new ArrayList<>();
        for (Claim c : claims.values()) {
            if (c.agent().equals(agent)) {
                theirs.add(c);
            }
        }
        theirs.forEach(this::drop);
        return theirs.size();
    }

    private void drop(Claim c) {
        removeObsPropertyByTemplate("claimed", c.id(), null, null, null, null);
        claims.remove(c.id());
        carried.remove(c.id());
    }
}
