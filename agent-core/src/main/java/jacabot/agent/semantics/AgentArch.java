package jacabot.agent.semantics;

import jacabot.agent.parser.AslParser;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import java.util.Collection;
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
    /**
     * Stops the system after {@code deadlineMs}, first telling every agent
     * {@code +jag_shutting_down(deadlineMs)} (Jason's {@code .stopMAS(T)}); by default at once.
     */
    default void stopMAS(long deadlineMs) {
        stopMAS();
    }

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

    /**
     * Creates an agent running {@code program} while the system runs (Jason's {@code .create_agent}).
     * {@return the name given, or null when this infrastructure cannot}
     */
    default String createAgent(String name, AgentProgram program, AslParser parser) {
        return null;
    }

    /** As {@link #createAgent}, for a copy of a running agent: its beliefs produce no events (Jason's {@code .clone}). */
    default String cloneAgent(String name, AgentProgram program, AslParser parser) {
        return null;
    }

    /** Stops and removes an agent (Jason's {@code .kill_agent}). {@return whether it existed} */
    default boolean killAgent(String name) {
        return false;
    }

    // ---- the directory facilitator (Jason's DF: which agent provides which service) ----------

    /** Registers {@code agent} as a provider of {@code service}. {@return whether there is a DF} */
    default boolean dfRegister(String agent, String service) {
        return false;
    }

    default boolean dfDeregister(String agent, String service) {
        return false;
    }

    /** {@return the providers of a service, or null when there is no DF} */
    default Collection<String> dfSearch(String service) {
        return null;
    }

    /** Subscribes {@code agent} to the providers of {@code service} (told as {@code provider(A, S)}). */
    default boolean dfSubscribe(String agent, String service) {
        return false;
    }
}
