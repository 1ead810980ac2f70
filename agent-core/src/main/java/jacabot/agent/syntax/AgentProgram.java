package jacabot.agent.syntax;

import java.util.List;

/**
 * A parsed AgentSpeak source: initial beliefs and rules in file order, initial goals, and plans.
 *
 * @param beliefs literals and rules ({@link Rule}) in file order
 */
public record AgentProgram(String file, List<Object> beliefs, List<Literal> goals, List<Plan> plans) {
    public AgentProgram {
        beliefs = List.copyOf(beliefs);
        goals = List.copyOf(goals);
        plans = List.copyOf(plans);
    }
}
