package jacabot.cartago;

import java.util.Objects;

/**
 * The identity of a workspace an agent has joined: its name and the node that hosts it
 * ({@value #LOCAL} for this process, {@code host:port} for a remote one).
 *
 * @param name the workspace's name on its node
 * @param node {@value #LOCAL}, or the address of the node
 */
public record WorkspaceId(String name, String node) {
    public static final String LOCAL = "local";

    public WorkspaceId {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(node, "node");
    }

    /** {@return a workspace of this process} */
    public static WorkspaceId local(String name) {
        return new WorkspaceId(name, LOCAL);
    }

    public boolean isLocal() {
        return LOCAL.equals(node);
    }

    /** {@return the name; CArtAgO's spelling} */
    public String getName() {
        return name;
    }

    /**
     * {@return the name for a local workspace, {@code name@host:port} for a remote one}: also the
     * {@link ArtifactId#workspace()} of its artifacts as agents see them
     */
    public String getFullName() {
        return isLocal() ? name : name + "@" + node;
    }

    @Override
    public String toString() {
        return getFullName();
    }
}
