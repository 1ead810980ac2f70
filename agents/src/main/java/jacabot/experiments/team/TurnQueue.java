package jacabot.experiments.team;

import jacabot.cartago.AgentId;
import java.util.ArrayList;
import java.util.List;

/**
 * A first-come-first-served queue of agents for one place that takes one robot at a time (the
 * charger, the storage area): the head has the turn until it leaves. Not an artifact: the team's
 * artifacts keep one each and publish it as an observable property after every change.
 */
final class TurnQueue {
    private final List<AgentId> queue = new ArrayList<>();

    /** Joins the tail; {@return whether the queue changed} (false when queued already) */
    boolean join(AgentId agent) {
        if (queue.contains(agent)) {
            return false;
        }
        return queue.add(agent);
    }

    /** Leaves the queue wherever the agent stands; {@return whether the queue changed} */
    boolean leave(AgentId agent) {
        return queue.remove(agent);
    }

    /**
     * The head lets the next one go first (a robot that cannot reach the place keeps the others
     * from it otherwise); {@return whether the queue changed} (false unless the agent is the head
     * and another is queued)
     */
    boolean yieldTurn(AgentId agent) {
        if (queue.size() < 2 || !queue.get(0).equals(agent)) {
            return false;
        }
        queue.set(0, queue.get(1));
        queue.set(1, agent);
        return true;
    }

    /** {@return whether the agent has the turn, or is not queued (a wait for it ends either way)} */
    boolean headOrGone(AgentId agent) {
        return queue.isEmpty() || queue.get(0).equals(agent) || !queue.contains(agent);
    }

    boolean contains(AgentId agent) {
        return queue.contains(agent);
    }

    /** {@return the queued agents, the head first} */
    List<AgentId> agents() {
        return List.copyOf(queue);
    }

    /** {@return the queued agents' names, the head first} */
    List<String> names() {
        return queue.stream().map(AgentId::name).toList();
    }
}
