package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import jacabot.cartago.ObsProperty;
import jacabot.cartago.OpFeedbackParam;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A team's task board (thesis Chapter 6, coordination among robots; after the claims of Jason's
 * gold-miners, kept in an artifact as JaCa would): a robot that sights a cylinder claims it by its
 * estimated place on the floor, so that no other robot goes for it, and releases the claim when it
 * gives up or completes it when the cylinder is in the storage area.
 *
 * <p>A claim is a place: two places closer than the board's radius (0.1 m unless {@code init} says
 * otherwise) are the same cylinder, as a robot's estimate from its camera is rough. Claims are by
 * place because that is what a robot perceives ({@code cylinderSighted(Offset, Distance)} from
 * where it stands); a cylinder's name is the world file's, which no robot sees.
 *
 * <p>Observable properties: {@code claimed(Id, Agent, X, Z)}, one per claim (Agent an atom), and
 * {@code completed(N)}, the team's deliveries. Operations: {@code claim(X, Z)}, {@code claim(X, Z,
 * ?Id)}, {@code release(Id)}, {@code complete(Id)}, {@code releaseAll}. Every operation is one
 * artifact step, so two agents can never hold claims on one cylinder, however their calls
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
    /** A cylinder picked up voids other agents' claims within this many radii of it. */
    static final double TAKE_REACH = 1.5;

    private record Claim(int id, AgentId agent, ObsProperty property) {
        double x() {
            return property.doubleValue(2);
        }

        double z() {
            return property.doubleValue(3);
        }
    }

    private final Map<Integer, Claim> claims = new LinkedHashMap<>();
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

    /** Claims the cylinder at (x, z) for the calling agent; see {@link #claim(double, double, OpFeedbackParam)}. */
    @OPERATION
    void claim(double x, double z) {
        claim(x, z, new OpFeedbackParam<>());
    }

    /**
     * Claims the cylinder at (x, z) for the calling agent and gives the claim's id. Fails with
     * {@code claimed_by(Agent, Id)} when another agent's claim lies within the radius. A claim of
     * the caller's own there is the same claim: its id comes back and its place becomes (x, z),
     * the newer estimate.
     */
    @OPERATION
    void claim(double x, double z, OpFeedbackParam<Integer> id) {
        AgentId me = getCurrentOpAgentId();
        Claim mine = null;
        for (Claim c : claims.values()) {
            if (Math.hypot(c.x() - x, c.z() - z) < radius) {
                if (!c.agent().equals(me)) {
                    failed(c.agent().name() + " has claimed the cylinder at (" + c.x() + ", " + c.z() + ")",
                            "claimed_by", c.agent(), c.id());
                }
                mine = mine == null ? c : mine;
            }
        }
        if (mine != null) {
            mine.property().updateValues(mine.id(), me, x, z);
            id.set(mine.id());
            return;
        }
        id.set(newClaim(me, x, z));
    }

    /**
     * The caller has picked up the cylinder at (x, z): the cylinder is its own in fact, so every
     * other agent's claim within {@link #TAKE_REACH} radii of it is void (dropped: two robots'
     * estimates of one cylinder seen from afar may lie further apart than the radius), the caller's
     * other claims are released (a robot carries one cylinder), and its claim within the radius
     * there is given back with its place updated, made if need be.
     */
    @OPERATION
    void take(double x, double z, OpFeedbackParam<Integer> id) {
        AgentId me = getCurrentOpAgentId();
        Claim kept = null;
        for (Claim c : List.copyOf(claims.values())) {
            double d = Math.hypot(c.x() - x, c.z() - z);
            if (d < radius && c.agent().equals(me) && kept == null) {
                kept = c;
            } else if (d < TAKE_REACH * radius || c.agent().equals(me)) {
                drop(c);
            }
        }
        if (kept != null) {
            kept.property().updateValues(kept.id(), me, x, z);
            id.set(kept.id());
            return;
        }
        id.set(newClaim(me, x, z));
    }

    /** Gives up the caller's claim {@code id}: another agent may claim that cylinder now. */
    @OPERATION
    void release(int id) {
        drop(owned(id));
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

    private int newClaim(AgentId agent, double x, double z) {
        int next = ++lastId;
        claims.put(next, new Claim(next, agent, defineObsProperty("claimed", next, agent, x, z)));
        return next;
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
        removeObsPropertyByTemplate("claimed", c.id(), null, null, null);
        claims.remove(c.id());
    }
}
