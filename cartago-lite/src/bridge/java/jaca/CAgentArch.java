package jaca;

import jacabot.agent.runtime.LocalArch;

/**
 * JaCa's agent architecture under its own name, so that a CArtAgO project's {@code .mas2j} keeps
 * its {@code agentArchClass jaca.CAgentArch} lines and only its {@code environment:} changes to
 * {@code jacabot.cartago.bridge.CartagoEnvironment}. It is {@link jacabot.cartago.bridge.CAgentArch}.
 */
public class CAgentArch extends jacabot.cartago.bridge.CAgentArch {
    public CAgentArch(LocalArch local) {
        super(local);
    }
}
