package jacabot.agent.runtime;

import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.Literal;
import java.util.List;

/**
 * A Jason-style environment: percepts for each agent and the execution of their actions. An
 * implementation reports each action's outcome with {@code action.succeed()}/{@code fail(...)} and
 * {@code agent.actionExecuted(action)}, now or later, from any thread.
 */
public interface Environment {
    /** Called once with the arguments of the {@code environment:} entry of the project. */
    default void init(LocalMAS mas, List<String> args) {
    }

    /** {@return the agent's percepts, or null when they did not change} */
    default List<Literal> percepts(String agent) {
        return null;
    }

    void execute(String agent, ActionExec action, Agent ag);

    default void stop() {
    }
}
