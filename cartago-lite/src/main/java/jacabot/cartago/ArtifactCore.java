package jacabot.cartago;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The runtime side of one artifact: its lock (one operation step at a time), its properties, its
 * observers and the step now running. Kept apart from {@link Artifact} so that artifact classes
 * see only CArtAgO's API.
 */
final class ArtifactCore {
    private final Artifact artifact;
    private final ArtifactId id;
    private final ArtifactType type;
    private final Workspace workspace;
    private final ReentrantLock lock = new ReentrantLock();
    /** Signalled at every commit, so that waiting guards are checked again. */
    private final Condition changed = lock.newCondition();
    private final PropertyStore properties = new PropertyStore(this);
    private final Map<AgentId, ArtifactObserver> observers = new LinkedHashMap<>();
    private OpExecution current;
    /** Declared out ports and the artifacts linked to each, in link order. */
    private final Map<String, List<ArtifactId>> ports = new ConcurrentHashMap<>();
    private volatile boolean disposed;
    /** Made at the first operation recorded ({@link Workspace#recordOperations}). */
    private volatile OperationHistory history;

    ArtifactCore(Artifact artifact, ArtifactId id, ArtifactType type, Workspace workspace) {
        this.artifact = artifact;
        this.id = id;
        this.type = type;
        this.workspace = workspace;
        ARTIFACT_INFO info = artifact.getClass().getAnnotation(ARTIFACT_INFO.class);
        if (info != null) {
            for (OUTPORT port : info.outports()) {
                ports.put(port.name(), new CopyOnWriteArrayList<>());
            }
        }
    }

    /** Links the out port {@code port} to {@code target}. */
    void link(String port, ArtifactId target) {
        List<ArtifactId> linked = ports.get(port);
        if (linked == null) {
            throw new OpFailedException("artifact " + id.name() + " has no out port " + port
                    + " (declare it with @ARTIFACT_INFO(outports = @OUTPORT(name = \"" + port + "\")))", "unknown_port", port);
        }
        if (!linked.contains(target)) {
            linked.add(target);
        }
    }

    /** {@return the artifacts linked to {@code port}, or null if there is no such port} */
    List<ArtifactId> linked(String port) {
        List<ArtifactId> linked = ports.get(port);
        return linked == null ? null : List.copyOf(linked);
    }

    /** Adds a completed operation to this artifact's log, keeping {@code lastN} per agent. */
    void recordOperation(OperationRecord record, int lastN) {
        OperationHistory h = history;
        if (h == null) {
            synchronized (this) {
                h = history;
                if (h == null) {
                    h = new OperationHistory();
                    history = h;
                }
            }
        }
        h.add(record, lastN);
    }

    /** {@return the operations recorded on this artifact, in completion order} */
    List<OperationRecord> operationLog() {
        OperationHistory h = history;
        return h == null ? List.of() : h.records();
    }

    Artifact artifact() {
        return artifact;
    }

    ArtifactId id() {
        return id;
    }

    ArtifactType type() {
        return type;
    }

    Workspace workspace() {
        return workspace;
    }

    ReentrantLock lock() {
        return lock;
    }

    Condition changed() {
        return changed;
    }

    PropertyStore properties() {
        return properties;
    }

    boolean isDisposed() {
        return disposed;
    }

    /** {@return the step running on this thread} @throws IllegalStateException outside a step */
    OpExecution current() {
        checkInStep();
        return current;
    }

    void checkInStep() {
        if (!lock.isHeldByCurrentThread() || current == null) {
            throw new IllegalStateException("artifact primitives of " + id.name()
                    + " can only be used inside one of its operations, init or guards");
        }
    }

    /** Makes {@code step} the running step; the caller holds the lock. {@return the previous one} */
    OpExecution begin(OpExecution step) {
        OpExecution previous = current;
        current = step;
        return previous;
    }

    void end(OpExecution previous) {
        current = previous;
    }

    /** Publishes the pending property changes to the observers and wakes waiting guards. */
    void commit() {
        List<PropertyStore.Change> changes = properties.commit();
        for (PropertyStore.Change c : changes) {
            for (Map.Entry<AgentId, ArtifactObserver> o : observers.entrySet()) {
                ArtifactObserver observer = o.getValue();
                if (c.before() == null) {
                    notify(o.getKey(), () -> observer.propertyAdded(id, c.after()));
                } else if (c.after() == null) {
                    notify(o.getKey(), () -> observer.propertyRemoved(id, c.before()));
                } else {
                    notify(o.getKey(), () -> observer.propertyUpdated(id, c.before(), c.after()));
                }
            }
        }
        changed.signalAll();
    }

    void rollback() {
        properties.rollback();
    }

    /** Commits, then tells every observer (or {@code target} alone, if not null) the signal. */
    void signal(AgentId target, String type, List<Object> args) {
        commit();
        if (target == null) {
            for (Map.Entry<AgentId, ArtifactObserver> o : observers.entrySet()) {
                ArtifactObserver observer = o.getValue();
                notify(o.getKey(), () -> observer.signalled(id, type, args));
            }
        } else {
            ArtifactObserver observer = workspace.observerOf(target);
            if (observer != null) {
                notify(target, () -> observer.signalled(id, type, args));
            }
        }
    }

    /** Adds an observer under the lock; {@return false if it was there already} */
    boolean addObserver(AgentId agent, ArtifactObserver observer) {
        if (observers.containsKey(agent)) {
            return false;
        }
        observers.put(agent, observer);
        List<PropertySnapshot> snapshot = properties.committedSnapshot();
        notify(agent, () -> observer.focused(id, snapshot));
        return true;
    }

    /** Removes an observer under the lock; {@return false if it was not observing} */
    boolean removeObserver(AgentId agent) {
        ArtifactObserver observer = observers.remove(agent);
        if (observer == null) {
            return false;
        }
        List<PropertySnapshot> snapshot = properties.committedSnapshot();
        notify(agent, () -> observer.focusEnded(id, snapshot, false));
        return true;
    }

    /** {@return the observing agents, in focus order; the caller holds the lock} */
    List<AgentId> observers() {
        return new ArrayList<>(observers.keySet());
    }

    /** Marks the artifact disposed and tells its observers; the caller holds the lock. */
    List<AgentId> markDisposed() {
        disposed = true;
        List<PropertySnapshot> snapshot = properties.committedSnapshot();
        List<AgentId> former = new ArrayList<>(observers.keySet());
        for (Map.Entry<AgentId, ArtifactObserver> o : observers.entrySet()) {
            ArtifactObserver observer = o.getValue();
            notify(o.getKey(), () -> observer.focusEnded(id, snapshot, true));
        }
        observers.clear();
        changed.signalAll();
        return former;
    }

    private void notify(AgentId agent, Runnable event) {
        workspace.scheduler().deliver(() -> {
            try {
                event.run();
            } catch (RuntimeException e) {
                workspace.logger().warning(id.name(), "observer of agent " + agent + " failed", e);
            }
        });
    }

    @Override
    public String toString() {
        return id.name();
    }
}
