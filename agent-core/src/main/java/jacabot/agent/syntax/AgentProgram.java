package jacabot.agent.syntax;

import java.util.List;

/**
 * A parsed AgentSpeak source: initial beliefs and rules in file order, initial goals, and plans.
 *
 * @param beliefs literals and rules ({@link Rule}) in file order
 * @param functions arithmetic functions the program registers
 */
public record AgentProgram(String file, List<Object> beliefs, List<Literal> goals, List<Plan> plans,
        List<UserFunction> functions) {
    public AgentProgram {
        beliefs = List.copyOf(beliefs);
        goals = List.copyOf(goals);
        plans = List.copyOf(plans);
        functions = List.copyOf(functions);
    }

    public AgentProgram(String file, List<Object> beliefs, List<Literal> goals, List<Plan> plans) {
        this(file, beliefs, goals, plans, List.of());
    }

    /**
     * An arithmetic function computed by a rule, {@code { register_function("f", N, "p") }}: f of N
     * arguments is the last argument of the first solution of {@code p(A1, ..., AN, R)}.
     */
    public record UserFunction(String name, int arity, String predicate) {
    }
}
