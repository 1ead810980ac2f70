package jacabot.agent.runtime;

import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.agent.syntax.Literal;
import java.util.List;

/**
 * No environment, as a Jason project without an {@code environment:} entry: no percepts, and every
 * action fails with {@code error_msg("no environment configured!")} and the reason {@code noenv}.
 */
public final class DefaultEnvironment implements Environment {
    @Override
    public void execute(String agent, ActionExec action, Agent ag) {
        action.fail("no environment configured!", List.of(Literal.atom("noenv")));
        ag.actionExecuted(action);
    }
}
