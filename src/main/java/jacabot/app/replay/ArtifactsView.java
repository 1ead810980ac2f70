package jacabot.app.replay;

import jacabot.app.inspector.ArtifactInfo;
import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.Workspace;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Supplier;

/**
 * A live run's workspace for the inspector's artifacts panel: each artifact agents can use (one
 * with operations, not the workspace's own), its class, its operations and who focuses on it now. Read from the
 * inspector's threads: the workspace's lists are safe to read while the run goes on.
 */
final class ArtifactsView {
    private static final String INFRASTRUCTURE = Workspace.class.getPackageName() + ".";

    private ArtifactsView() {
    }

    static Supplier<Map<String, ArtifactInfo>> of(Workspace ws) {
        return () -> {
            var out = new TreeMap<String, ArtifactInfo>();
            for (ArtifactId id : ws.artifacts()) {
                var ops = ws.operationsOf(id);
                // not the workspace's own (workspace, console, the agents' bodies): every run has them
                boolean own = id.type().startsWith(INFRASTRUCTURE) && id.type().indexOf('.', INFRASTRUCTURE.length()) < 0;
                if (!ops.isEmpty() && !own) {
                    out.put(id.name(), new ArtifactInfo(id.type(), ops, ws.observersOf(id).stream().map(AgentId::name).toList()));
                }
            }
            return out;
        };
    }
}
