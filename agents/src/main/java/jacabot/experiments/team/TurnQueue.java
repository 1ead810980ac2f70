package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import java.util.ArrayList;
import java.util.List;

/**
 * A queue of agents for one place that takes one robot at a time (the charger, the storage area),
 * ordered by need: an agent joins before the first one whose need is greater (a lower figure is a
 * greater need: a battery's energy), after those with the same need, so that equal needs are served
 * in the order of arrival (the storage area, where every need is the same). The head has the turn;
 * once it has taken it ({@link #take}) it keeps it until it leaves or yields, and nobody is put
 * before it: a robot on the charger is never sent off for a needier one. A head that has not taken
 * its turn yet (a robot still on its way) is overtaken by a needier arrival.
 * An agent that has {@linkplain #arrive arrived} (a robot waiting at the place) ranks before every
 * one that has not (a robot that booked its place from afar and still has to travel): a needier
 * robot far away does not keep the ones standing at the charger waiting while it travels. Those not
 * arrived are ordered by need, those arrived by their arrival: a robot standing at the charger is
 * not overtaken by needier robots arriving after it (one waited 141 s there while two needier ones
 * went first, team world 3 with four robots; a robot waiting stands still and spends 0.5 W).
 * Not an artifact: the team's artifacts keep one each and publish it as an observable property
 * after every change.
 */
final class TurnQueue {
    private record Place(AgentId agent, double need, boolean arrived) {
        /**
         * Whether this place, placed now, goes before {@code other}: arrived first; among those not
         * arrived the lower need; among those arrived nobody (the order of arrival).
         */
        boolean before(Place other) {
            return arrived != other.arrived ? arrived : !arrived && need < other.need;
        }
    }

    private final List<Place> queue = new ArrayList<>();
    /** Whether the head has taken its turn (then it keeps the first place). */
    private boolean taken;

    /** Joins in the order of arrival (every need the same); {@return whether the queue changed} */
    boolean join(AgentId agent) {
        return join(agent, Double.POSITIVE_INFINITY);
    }

    /**
     * Joins by need (lower first), or moves an agent queued already to the place its new need
     * gives it (the head that has taken its turn keeps it); {@return whether the order changed}
     */
    boolean join(AgentId agent, double need) {
        int at = indexOf(agent);
        return place(agent, new Place(agent, need, at >= 0 && queue.get(at).arrived()));
    }

    /**
     * The agent stands at the place now: it ranks before every agent that has not arrived (joining
     * behind every need if it was not queued); {@return whether the order changed}
     */
    boolean arrive(AgentId agent) {
        int at = indexOf(agent);
        double need = at >= 0 ? queue.get(at).need() : Double.POSITIVE_INFINITY;
        return place(agent, new Place(agent, need, true));
    }

    /** Puts the agent's place where it ranks (the head that has taken its turn keeps it). */
    private boolean place(AgentId agent, Place p) {
        int at = indexOf(agent);
        if (at == 0 && taken) {
            queue.set(0, p);
            return false;
        }
        List<AgentId> before = agents();
        if (at >= 0) {
            queue.remove(at);
        }
        int i = taken ? 1 : 0;
        while (i < queue.size() && !p.before(queue.get(i))) {
            i++;
        }
        queue.add(i, p);
        return !agents().equals(before);
    }

    /** The head takes its turn: nobody is put before it until it leaves or yields; {@return whether it is the head} */
    boolean take(AgentId agent) {
        if (indexOf(agent) != 0) {
            return false;
        }
        taken = true;
        return true;
    }

    /** Leaves the queue wherever the agent stands; {@return whether the queue changed} */
    boolean leave(AgentId agent) {
        int at = indexOf(agent);
        if (at < 0) {
            return false;
        }
        queue.remove(at);
        if (at == 0) {
            taken = false;
        }
        return true;
    }

    /**
     * The head lets the next one go first and stands second (a robot that cannot reach the place
     * keeps the others from it otherwise); {@return whether the queue changed} (false unless the
     * agent is the head and another is queued)
     */
    boolean yieldTurn(AgentId agent) {
        if (queue.size() < 2 || !queue.get(0).agent().equals(agent)) {
            return false;
        }
        queue.add(1, queue.remove(0));
        taken = false;
        return true;
    }

    /** {@return whether the agent has the turn, or is not queued (a wait for it ends either way)} */
    boolean headOrGone(AgentId agent) {
        return queue.isEmpty() || indexOf(agent) <= 0;
    }

    boolean contains(AgentId agent) {
        return indexOf(agent) >= 0;
    }

    /** {@return the queued agents, the head first} */
    List<AgentId> agents() {
        return queue.stream().map(Place::agent).toList();
    }

    /** {@return the needs of the agents that have arrived, behind the head, in the queue's order} */
    List<Double> arrivedNeeds() {
        return queue.stream().skip(1).filter(Place::arrived).map(Place::need).toList();
    }

    /** {@return the names of the agents that have arrived, behind the head, in the queue's order} */
    List<String> arrivedNames() {
        return queue.stream().skip(1).filter(Place::arrived).map(p -> p.agent().name()).toList();
    }

    /** {@return the queued agents' names, the head first} */
    List<String> names() {
        return queue.stream().map(p -> p.agent().name()).toList();
    }

    private int indexOf(AgentId agent) {
        for (int i = 0; i < queue.size(); i++) {
            if (queue.get(i).agent().equals(agent)) {
                return i;
            }
        }
        return -1;
    }
}
