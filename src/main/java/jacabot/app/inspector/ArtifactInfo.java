package jacabot.app.inspector;

import java.util.List;

/**
 * An artifact of a live run's workspace as the artifacts panel shows it: its class, the
 * operations agents may use (name/arity) and the agents that focus on it, in focus order.
 */
public record ArtifactInfo(String type, List<String> operations, List<String> focusedBy) {
    public ArtifactInfo {
        operations = List.copyOf(operations);
        focusedBy = List.copyOf(focusedBy);
    }
}
