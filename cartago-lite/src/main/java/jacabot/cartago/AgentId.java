package jacabot.cartago;

import java.util.Objects;

/**
 * The identity of an agent working in a workspace: its name, unique in the workspace.
 *
 * @param name the agent's name
 */
public record AgentId(String name) {
    public AgentId {
        Objects.requireNonNull(name, "name");
    }

    /** {@return the agent's name; CArtAgO's spelling of {@link #name()}} */
    public String getAgentName() {
        return name;
    }

    @Override
    public String toString() {
        return name;
    }
}
