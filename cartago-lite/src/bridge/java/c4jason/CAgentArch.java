package c4jason;

import jacabot.agent.runtime.LocalArch;

/**
 * The agent architecture of CArtAgO 2's JaCa ({@code agentArchClass c4jason.CAgentArch}), for its
 * older examples. It is {@link jacabot.cartago.bridge.CAgentArch}.
 */
public class CAgentArch extends jacabot.cartago.bridge.CAgentArch {
    public CAgentArch(LocalArch local) {
        super(local);
    }
}
