package jacabot.cartago;

import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicReferenceArray;

/**
 * The artifact each agent's operations without a target went to ({@link OpResolver}), kept while
 * the workspace's live artifacts (the same {@link Workspace#cores()} list, made anew when one comes
 * or goes) and the agents' focus ({@link FocusBook#changes()}) stay as they were: the choice depends
 * on nothing else (an artifact's methods are its class's), and a robot's agent asks for the same few
 * operations at every control step, each of which asked every artifact in turn.
 */
final class OpRoutes {
    /** Operations of this many arguments or more are not kept. */
    private static final int ARITIES = 8;

    /** What the routes were worked out from, and the routes: agent, operation, arity. */
    private record State(List<ArtifactCore> live, long focus,
            Map<AgentId, Map<String, AtomicReferenceArray<ArtifactCore>>> routes) {
    }

    private volatile State state = new State(null, -1, Map.of());

    /** {@return the artifact the operation went to from the same artifacts and focus, or null} */
    ArtifactCore get(List<ArtifactCore> live, long focus, AgentId agent, String operation, int arity) {
        State s = state;
        if (s.live() != live || s.focus() != focus || arity >= ARITIES) {
            return null;
        }
        Map<String, AtomicReferenceArray<ArtifactCore>> ofAgent = s.routes().get(agent);
        AtomicReferenceArray<ArtifactCore> byArity = ofAgent == null ? null : ofAgent.get(operation);
        return byArity == null ? null : byArity.get(arity);
    }

    /**
     * Keeps the artifact the operation went to, worked out from {@code live} and the focus lists
     * after {@code focus} was read. A newer state replaced by an older one only costs lookups.
     */
    void put(List<ArtifactCore> live, long focus, AgentId agent, String operation, int arity, ArtifactCore core) {
        if (arity >= ARITIES) {
            return;
        }
        State s = state;
        if (s.live() != live || s.focus() != focus) {
            s = new State(live, focus, new ConcurrentHashMap<>());
            state = s;
        }
        s.routes().computeIfAbsent(agent, a -> new ConcurrentHashMap<>())
                .computeIfAbsent(operation, o -> new AtomicReferenceArray<>(ARITIES)).set(arity, core);
    }
}
