package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import java.util.List;

/**
 * The agent's architecture: how it perceives, acts, communicates and tells time. The local
 * infrastructure, the JaCa bridge and tests plug in here.
 */
public interface AgentArch {

    /**
     * Called at the start of each reasoning cycle, on the agent's thread: the place to apply
     * incremental changes (new beliefs, events) the architecture has queued.
     */
    default void sense(Agent agent) {
    }

    /** {@return the current percepts, or null when nothing changed since the last call} */
    default List<Literal> perceive() {
        return null;
    }

    /**
     * Starts an environment action. The architecture reports its outcome later, from any thread,
     * through {@link Agent#actionExecuted(ActionExec)} after {@code succeed} or {@code fail}.
     */
    default void act(ActionExec action, Agent agent) {
        action.fail("no environment to execute '" + action.action() + "'", List.of());
        agent.actionExecuted(action);
    }

    /** Delivers a message to another agent. {@return whether the receiver exists} */
    default boolean sendMessage(Message m) {
        return false;
    }

    /** {@return the names of every agent of the system} */
    default List<String> agentNames() {
        return List.of();
    }

    /** Writes one console line; the agent's name is already in it ({@code [name] text}). */
    default void console(String line) {
        System.out.println(line);
    }

    /** Stops the whole multi-agent system ({@code .stopMAS}). */
    default void stopMAS() {
    }

    default Clock clock() {
        return Clock.wall();
    }

    /** {@return false while the architecture has input for the agent (e.g. new percepts)} */
    default boolean canSleep() {
        return true;
    }

    /** Called when the agent has something new to do (mail, feedback, a timer), from any thread. */
    default void wake() {
    }
}
