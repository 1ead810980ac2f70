package jacabot.app.replay;

import jacabot.app.inspector.ArtifactInfo;
import jacabot.app.inspector.ArtifactInfo.LoggedOperation;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.OperationRecord;
import jacabot.cartago.Workspace;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Supplier;

/**
 * A live run's workspace for the inspector's artifacts panel: each artifact agents can use (one
 * with operations, not the workspace's own), its class, its operations, who focuses on it now and
 * its operation log. Read from the inspector's threads: the workspace's lists are safe to read
 * while the run goes on. The workspace records operations only from the panel's first reading on,
 * so a run nobody looks at pays nothing for it (and recording does not change the run).
 */
final class ArtifactsView {
    /** The operations kept per agent and artifact: the panel shows the latest. */
    static final int LAST_OPERATIONS = 8;
    private static final String INFRASTRUCTURE = Workspace.class.getPackageName() + ".";

    private ArtifactsView() {
    }

    static Supplier<Map<String, ArtifactInfo>> of(Workspace ws) {
        return () -> {
            if (!ws.recordsOperations()) {
                ws.recordOperations(LAST_OPERATIONS);
            }
            var out = new TreeMap<String, ArtifactInfo>();
            for (ArtifactId id : ws.artifacts()) {
                var ops = ws.operationsOf(id);
                // not the workspace's own (workspace, console, the agents' bodies): every run has them
                boolean own = id.type().startsWith(INFRASTRUCTURE) && id.type().indexOf('.', INFRASTRUCTURE.length()) < 0;
                if (!ops.isEmpty() && !own) {
                    out.put(id.name(), new ArtifactInfo(id.type(), ops, ws.observersOf(id).stream().map(AgentId::name).toList(),
                            logged(ws.operationLog(id))));
                }
            }
            return out;
        };
    }

    private static List<LoggedOperation> logged(List<OperationRecord> records) {
        return records.stream().map(r -> new LoggedOperation(r.startMillis(), r.endMillis(), r.agent(), r.operation(),
                r.succeeded() ? "ok" : r.failure())).toList();
    }
}
