package jacabot.cartago;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The focus bookkeeping of a workspace: the agents that joined, the observer and body of each,
 * and which artifacts each observes. An artifact's own observer list (in {@link ArtifactCore},
 * under its lock) is the authority for event delivery; the per-agent lists here serve operation
 * resolution and queries, and are kept in step by {@link #focus} and {@link #stopFocus}.
 */
final class FocusBook {
    /** One joined agent. */
    record Entry(AgentId id, ArtifactObserver observer, ArtifactId body, List<ArtifactId> focused) {
    }

    private final String workspace;
    private final Map<AgentId, Entry> agents = new ConcurrentHashMap<>();
    /** Moved after each change to the agents or their focus lists: see {@link #changes}. */
    private final AtomicLong changes = new AtomicLong();

    FocusBook(String workspace) {
        this.workspace = workspace;
    }

    /**
     * {@return how many times the agents or their focus lists changed} Counted after each change,
     * so an answer worked out from the lists after reading the count is stale once it moves
     * ({@link OpRoutes}).
     */
    long changes() {
        return changes.get();
    }

    boolean has(AgentId agent) {
        return agents.containsKey(agent);
    }

    void add(AgentId agent, ArtifactObserver observer, ArtifactId body) {
        agents.put(agent, new Entry(agent, observer, body, new CopyOnWriteArrayList<>()));
        changes.incrementAndGet();
    }

    Entry get(AgentId agent) {
        return agents.get(agent);
    }

    void remove(AgentId agent) {
        agents.remove(agent);
        changes.incrementAndGet();
    }

    List<AgentId> agents() {
        return new ArrayList<>(agents.keySet());
    }

    List<ArtifactId> focusedBy(AgentId agent) {
        Entry entry = agents.get(agent);
        return entry == null ? List.of() : List.copyOf(entry.focused());
    }

    ArtifactObserver observerOf(AgentId agent) {
        Entry entry = agents.get(agent);
        return entry == null ? null : entry.observer();
    }

    /** Makes {@code agent} observe {@code core}: it gets the current properties, then every change. */
    void focus(AgentId agent, ArtifactCore core) {
        Entry entry = agents.get(agent);
        if (entry == null) {
            throw new OpFailedException("agent " + agent + " has not joined workspace " + workspace, "unknown_agent", agent.name());
        }
        if (core.artifact() instanceof AgentBodyArtifact) {
            // Bodies lock their target while focusing; two bodies focusing each other would deadlock.
            throw new OpFailedException("agent bodies cannot be focused", "cannot_focus", core.id().name());
        }
        core.lock().lock();
        try {
            if (core.isDisposed()) {
                throw new OpFailedException("no artifact " + core.id().name() + " in workspace " + workspace,
                        "unknown_artifact", core.id().name());
            }
            if (core.addObserver(agent, entry.observer())) {
                entry.focused().add(core.id());
                changes.incrementAndGet();
            }
        } finally {
            core.lock().unlock();
        }
    }

    /** Ends {@code agent}'s observation of {@code core}. */
    void stopFocus(AgentId agent, ArtifactCore core) {
        core.lock().lock();
        try {
            if (!core.removeObserver(agent)) {
                throw new OpFailedException("agent " + agent + " is not focusing " + core.id().name(),
                        "not_focused", core.id().name());
            }
        } finally {
            core.lock().unlock();
        }
        Entry entry = agents.get(agent);
        if (entry != null) {
            entry.focused().remove(core.id());
        }
        changes.incrementAndGet();
    }

    /** Forgets a disposed artifact in the lists of its former observers. */
    void forget(ArtifactId artifact, List<AgentId> former) {
        for (AgentId agent : former) {
            Entry entry = agents.get(agent);
            if (entry != null) {
                entry.focused().remove(artifact);
            }
        }
        changes.incrementAndGet();
    }
}
