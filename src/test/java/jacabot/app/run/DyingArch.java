package jacabot.app.run;

import jacabot.agent.runtime.LocalArch;
import jacabot.agent.semantics.ActionExec;
import jacabot.agent.semantics.Agent;
import jacabot.cartago.bridge.CAgentArch;

/**
 * An agent architecture whose thread dies a while after the robot connected, as a runaway rule's
 * StackOverflowError kills it (docs/reliability.md, fault 3): for {@link ProcessFaultsTest}.
 */
public final class DyingArch extends CAgentArch {
    private int forwards;
    private boolean dying;

    public DyingArch(LocalArch local) {
        super(local);
    }

    /** The robot's {@code forward} or {@code setSpeeds} goes out, and at the N-th the agent's next cycle dies: the robot is moving then. */
    @Override
    public void act(ActionExec action, Agent agent) {
        super.act(action, agent);
        String act = action.action().toString();
        if ((act.startsWith("forward") || act.startsWith("setSpeeds"))
                && ++forwards >= Integer.getInteger("jacabot.test.dieAfter", 2)) {
            dying = true;
        }
    }

    @Override
    public void sense(Agent agent) {
        super.sense(agent);
        if (dying) {
            throw new StackOverflowError("simulated: a rule that recurses without end");
        }
    }
}
