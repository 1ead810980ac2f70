package jacabot.app.inspector;

import java.util.List;

/**
 * An artifact of a live run's workspace as the artifacts panel shows it: its class, the
 * operations agents may use (name/arity), the agents that focus on it, in focus order, and its
 * operation log: the last operations each agent ran on it, in the order they completed.
 */
public record ArtifactInfo(String type, List<String> operations, List<String> focusedBy, List<LoggedOperation> log) {
    public ArtifactInfo {
        operations = List.copyOf(operations);
        focusedBy = List.copyOf(focusedBy);
        log = List.copyOf(log);
    }

    /**
     * One completed operation: from {@code start} to {@code end} (simulated ms), for {@code agent},
     * {@code outcome} {@code "ok"} or the failure's reason.
     */
    public record LoggedOperation(long start, long end, String agent, String operation, String outcome) {
    }
}
