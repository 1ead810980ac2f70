package jacabot.agent.semantics;

import jacabot.agent.syntax.Plan;

/** Observes an agent's deliberation (tracing, latency measurements); runs on the agent's thread. */
@FunctionalInterface
public interface PlanListener {
    /** A plan was chosen for an event and its intended means is about to run. */
    void planSelected(Event event, Plan plan);
}
