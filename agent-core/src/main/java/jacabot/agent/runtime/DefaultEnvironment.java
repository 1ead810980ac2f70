package jacabot.agent.runtime;

import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import java.util.List;

/** Jason's default environment: no percepts, and every action fails with a console note. */
public final class DefaultEnvironment implements Environment {
    private LocalMAS mas;

    @Override
    public void init(LocalMAS mas, List<String> args) {
        this.mas = mas;
    }

    @Override
    public void execute(String agent, ActionExec action, Agent ag) {
        if (mas != null) {
            mas.console("[Environment] The action " + action.action() + " done by " + agent
                    + " is not implemented in the default environment.");
        }
        action.fail("", List.of());
        ag.actionExecuted(action);
    }
}
