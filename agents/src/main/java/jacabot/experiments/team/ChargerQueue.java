package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import jacabot.cartago.Artifact;
import jacabot.cartago.GUARD;
import jacabot.cartago.OPERATION;
import java.util.List;

/**
 * The queue for a team's one charger (thesis Chapter 6, coordination among robots): a robot whose
 * battery runs low asks for the charger and waits its turn, so that two robots never push each
 * other off the charging area. The queue is ordered by need: the robot with the least energy
 * first, equal needs in the order of arrival. Its head takes the charger when its wait ends and
 * holds it until it leaves the queue (nobody is put before it then), or lets the next one go first
 * when it cannot reach the charger; a head still on its way is overtaken by a needier robot. A
 * robot waiting at the charger ({@code awaitCharger}) ranks before every robot that booked its
 * place from afar and has not arrived yet, whatever their needs: it does not wait while another
 * travels to a charger that stands free. The robots waiting at the charger are served in the order
 * they arrived, so that none waits there while needier ones arriving after it go first.
 *
 * <p>Observable properties: {@code chargerQueue(List)}, the agents in order (atoms), the head
 * first; {@code chargerWaiting(List)}, the energies of the robots waiting at the charger behind the
 * head, in the queue's order (so that the robot on it can see a needier one). Operations:
 * {@code requestCharger(Energy)} (joins by need; already queued, moves to the
 * place its new need gives it), {@code requestCharger} (joins behind every need, in the order of
 * arrival; already queued, keeps its place), {@code awaitCharger} (the caller has arrived: it ranks
 * before those that have not; waits, without holding the
 * artifact, until the caller is the head, then holds the charger; joins first if need be; fails if
 * the caller leaves meanwhile), {@code yieldCharger} (the holder lets the next one have the charger
 * and waits behind it; alone, it keeps it), {@code leaveCharger} (leaves the queue wherever the
 * caller stands, the charger if it held it; not queued is fine). An agent that leaves the workspace
 * leaves the queue too ({@link #agentLeft}), so a robot whose agent died never keeps the others
 * from the charger.
 */
public class ChargerQueue extends Artifact {
    private final TurnQueue queue = new TurnQueue();

    void init() {
        defineObsProperty("chargerQueue", List.of());
        defineObsProperty("chargerWaiting", List.of());
    }

    /** Joins the queue behind every need, unless the caller is queued already (it keeps its place). */
    @OPERATION
    void requestCharger() {
        AgentId me = getCurrentOpAgentId();
        if (!queue.contains(me) && queue.join(me)) {
            publish();
        }
    }

    /** Joins the queue by need: before every robot with more energy than {@code energy} that does not hold the charger. */
    @OPERATION
    void requestCharger(double energy) {
        if (!(energy >= 0)) {
            failed("a robot's energy is a number of joules, at least 0; got " + energy, "bad_energy", energy);
        }
        queue.join(getCurrentOpAgentId(), energy);
        publish();
    }

    /**
     * Waits until the caller holds the charger (the queue's head), joining the queue if it has not.
     * Fails with {@code not_queued} if the caller leaves the queue meanwhile (a {@code leaveCharger}
     * from another of its intentions), so that no wait outlives its place.
     */
    @OPERATION
    void awaitCharger() {
        AgentId me = getCurrentOpAgentId();
        queue.arrive(me);
        publish();
        await("headOrGone", me);
        if (!queue.take(me)) {
            failed(me.name() + " left the charger's queue while waiting", "not_queued");
        }
        publish();
    }

    @GUARD
    boolean headOrGone(AgentId agent) {
        return queue.headOrGone(agent);
    }

    /** The holder lets the next in the queue have the charger and stands second (alone, it keeps the charger). */
    @OPERATION
    void yieldCharger() {
        if (queue.yieldTurn(getCurrentOpAgentId())) {
            publish();
        }
    }

    /** Leaves the queue (and the charger, if the caller held it). */
    @OPERATION
    void leaveCharger() {
        leave(getCurrentOpAgentId());
    }

    /** {@return the queued agents' names, the holder first; read it between two artifact steps} */
    public List<String> queued() {
        return queue.names();
    }

    /**
     * {@return the names of the robots waiting at the charger behind the holder (they have called
     * awaitCharger), in the queue's order; read it between two artifact steps}
     */
    public List<String> waiting() {
        return queue.arrivedNames();
    }

    @Override
    protected void agentLeft(AgentId agent) {
        leave(agent);
    }

    private void leave(AgentId agent) {
        if (queue.leave(agent)) {
            publish();
        }
    }

    /** Updates the properties that changed (an unchanged value is not signalled again). */
    private void publish() {
        List<AgentId> agents = queue.agents();
        if (!agents.equals(getObsProperty("chargerQueue").getValue())) {
            getObsProperty("chargerQueue").updateValue(agents);
        }
        List<Double> waiting = queue.arrivedNeeds();
        if (!waiting.equals(getObsProperty("chargerWaiting").getValue())) {
            getObsProperty("chargerWaiting").updateValue(waiting);
        }
    }
}
