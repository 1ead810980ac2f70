package jacabot.cartago.bridge;

import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserver;
import jacabot.cartago.WorkspaceId;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The workspaces one agent has joined, as in CArtAgO: there is always a <em>current</em> one, where
 * actions without an artifact or workspace annotation go. It is the last joined, or the last made
 * current ({@code cartago.set_current_wsp}); quitting it makes the one before current again.
 * Used from the agent's thread and from completion callbacks, hence synchronized.
 */
final class AgentSession {
    /** Told when the current workspace or the set of joined ones changed. */
    interface Listener {
        void changed(AgentSession session);
    }

    private final String agent;
    private final ArtifactObserver observer;
    /** Joined workspaces; the last is the current one. */
    private final List<JoinedWorkspace> joined = new ArrayList<>();
    private volatile Listener listener = s -> { };

    AgentSession(String agent, ArtifactObserver observer) {
        this.agent = agent;
        this.observer = observer;
    }

    /** {@return the observer through which the agent perceives in every workspace} */
    ArtifactObserver observer() {
        return observer;
    }

    String agent() {
        return agent;
    }

    void setListener(Listener l) {
        listener = l;
        l.changed(this);
    }

    /** Adds (or moves) a workspace to the end: it becomes current. */
    void joined(JoinedWorkspace w) {
        synchronized (this) {
            joined.removeIf(j -> j.id().equals(w.id()));
            joined.add(w);
        }
        listener.changed(this);
    }

    synchronized Optional<JoinedWorkspace> current() {
        return joined.isEmpty() ? Optional.empty() : Optional.of(joined.get(joined.size() - 1));
    }

    /** {@return whether {@code id} is joined; then it becomes current} */
    boolean makeCurrent(WorkspaceId id) {
        JoinedWorkspace w = find(id).orElse(null);
        if (w == null) {
            return false;
        }
        joined(w);
        return true;
    }

    /** Removes a joined workspace (after its {@code quit}). */
    void quitted(JoinedWorkspace w) {
        synchronized (this) {
            joined.remove(w);
        }
        listener.changed(this);
    }

    synchronized Optional<JoinedWorkspace> find(WorkspaceId id) {
        return joined.stream().filter(j -> j.id().equals(id)).findFirst();
    }

    /** {@return the joined workspace called {@code name} (full name, or plain name, latest first)} */
    synchronized Optional<JoinedWorkspace> byName(String name) {
        for (int i = joined.size() - 1; i >= 0; i--) {
            WorkspaceId id = joined.get(i).id();
            if (id.getFullName().equals(name) || id.name().equals(name)) {
                return Optional.of(joined.get(i));
            }
        }
        return Optional.empty();
    }

    /** {@return the joined workspace that holds {@code artifact}} */
    synchronized Optional<JoinedWorkspace> holding(ArtifactId artifact) {
        return joined.stream().filter(j -> j.id().getFullName().equals(artifact.workspace())).findFirst();
    }

    synchronized List<JoinedWorkspace> all() {
        return List.copyOf(joined);
    }
}
