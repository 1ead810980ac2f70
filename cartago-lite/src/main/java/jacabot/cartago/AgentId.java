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

    // written out, with the values the record's generated methods give (see ArtifactId)
    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof AgentId a && name.equals(a.name);
    }

    @Override
    public int hashCode() {
        return name.hashCode();
    }

    @Override
    public String toString() {
        return name;
    }
}
