package jacabot.cartago;

import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The artifacts of one workspace, as CArtAgO's workspace keeps them: made (numbered in creation
 * order, named uniquely), found by id, name or number, and disposed. The usage interface and the
 * focus of each artifact are its {@link ArtifactCore}'s; the agents' side of focus is the
 * {@link FocusBook}'s, which a disposal tells.
 */
final class ArtifactRegistry {
    /** The workspace's own artifacts, which agents cannot dispose. */
    private static final Set<String> RESERVED = Set.of("workspace", "console");
    private static final Method DISPOSE_HOOK = hook("dispose");
    private static final Method AGENT_LEFT_HOOK = hook("agentLeft", AgentId.class);

    private final Workspace workspace;
    private final ArtifactFactory factory;
    private final FocusBook focus;
    private final AtomicInteger ids = new AtomicInteger();
    private final Set<String> names = ConcurrentHashMap.newKeySet();
    private final Map<String, ArtifactCore> byName = new ConcurrentHashMap<>();
    private final Map<Integer, ArtifactCore> byId = new ConcurrentSkipListMap<>();
    private volatile Live live;
    private volatile long artifactsVersion;

    /** The live artifacts as of a count of {@link #artifactsChanged}. */
    private record Live(long version, List<ArtifactCore> cores) {
    }

    ArtifactRegistry(Workspace workspace, ArtifactFactory factory, FocusBook focus) {
        this.workspace = workspace;
        this.factory = factory;
        this.focus = focus;
    }

    /** {@return the artifact class called {@code className}, loaded by the workspace's class loader} */
    Class<? extends Artifact> load(String className) {
        return factory.load(className);
    }

    /** Makes, binds and initialises an artifact; a failing {@code init} leaves no trace of it. */
    ArtifactId create(String artifactName, Class<? extends Artifact> type, Object[] params, AgentId creator) {
        String ws = workspace.getName();
        if (workspace.isClosed()) {
            throw new OpFailedException("workspace " + ws + " is closed", "workspace_closed");
        }
        if (artifactName == null || artifactName.isEmpty()) {
            throw new OpFailedException("an artifact needs a non-empty name", "bad_argument", 1);
        }
        ArtifactType artifactType = factory.typeOf(type);
        if (!names.add(artifactName)) {
            throw new OpFailedException("an artifact called " + artifactName + " already exists in workspace " + ws,
                    "duplicate_name", artifactName);
        }
        try {
            Artifact artifact = factory.instantiate(type);
            ArtifactId id = new ArtifactId(ids.incrementAndGet(), artifactName, type.getName(), ws, creator);
            ArtifactCore core = new ArtifactCore(artifact, id, artifactType, workspace);
            artifact.bind(core);
            registerDuringInit(core);
            try {
                factory.init(core, params);
            } catch (RuntimeException e) {
                unregister(core);
                core.lock().lock();
                try {
                    core.markDisposed();
                    artifactsChanged();
                } finally {
                    core.lock().unlock();
                }
                throw e;
            }
            byName.put(artifactName, core);
            artifactsChanged();
            return id;
        } catch (RuntimeException e) {
            names.remove(artifactName);
            throw e;
        }
    }

    /** Internal operations started by {@code init} need the artifact findable by id only. */
    private void registerDuringInit(ArtifactCore core) {
        byId.put(core.id().id(), core);
        artifactsChanged();
    }

    private void unregister(ArtifactCore core) {
        byId.remove(core.id().id());
        byName.remove(core.id().name(), core);
        artifactsChanged();
    }

    /** Disposes {@code core}: runs its hook, ends its observers' focus and forgets it. */
    void dispose(ArtifactCore core) {
        core.lock().lock();
        try {
            if (core.isDisposed()) {
                throw new OpFailedException("artifact " + core.id().name() + " is already disposed",
                        "unknown_artifact", core.id().name());
            }
            try {
                OpExecution.hook(core, null).runHook(DISPOSE_HOOK, new Object[0]);
            } catch (RuntimeException | Error e) {
                workspace.logger().warning(core.id().name(), "dispose() failed", e);
            }
            focus.forget(core.id(), core.markDisposed());
            artifactsChanged();
        } finally {
            core.lock().unlock();
        }
        unregister(core);
        names.remove(core.id().name());
    }

    /** Disposal asked by an agent: the workspace's own artifacts and bodies are refused. */
    void disposeFor(Object ref) {
        ArtifactCore core = resolve(ref);
        if (RESERVED.contains(core.id().name()) && core.id().creator() == null || core.artifact() instanceof AgentBodyArtifact) {
            throw new OpFailedException("artifact " + core.id().name() + " belongs to the workspace and cannot be disposed",
                    "cannot_dispose", core.id().name());
        }
        dispose(core);
    }

    /** {@return the live artifact an agent refers to: by ArtifactId, name or number} */
    ArtifactCore resolve(Object ref) {
        ArtifactCore core = null;
        if (ref instanceof ArtifactId) {
            ArtifactId id = (ArtifactId) ref;
            core = byId.get(id.id());
            core = core != null && core.id().equals(id) ? core : null;
        } else if (ref instanceof CharSequence) {
            core = byName.get(ref.toString());
        } else if (ref instanceof Number) {
            core = byId.get(((Number) ref).intValue());
        }
        if (core == null || core.isDisposed()) {
            throw new OpFailedException("no artifact " + ref + " in workspace " + workspace.getName(),
                    "unknown_artifact", String.valueOf(ref));
        }
        return core;
    }

    /** {@return the artifact numbered {@code id} (also while its {@code init} runs), or null} */
    ArtifactCore byId(int id) {
        return byId.get(id);
    }

    /** {@return the artifact called {@code artifactName} once made, or null} */
    ArtifactCore byName(String artifactName) {
        return byName.get(artifactName);
    }

    /** {@return every artifact known by id, oldest first (a live view)} */
    Collection<ArtifactCore> all() {
        return byId.values();
    }

    /**
     * {@return live artifacts, oldest first} Every operation without a target asks for them
     * ({@link OpResolver}), so the list is kept until an artifact comes or goes: it is stamped with
     * the {@link #artifactsChanged} count read before it was made.
     */
    List<ArtifactCore> cores() {
        Live known = live;
        long version = artifactsVersion;
        if (known != null && known.version() == version) {
            return known.cores();
        }
        List<ArtifactCore> cores = new ArrayList<>();
        for (ArtifactCore core : byId.values()) {
            if (!core.isDisposed() && byName.get(core.id().name()) == core) {
                cores.add(core);
            }
        }
        List<ArtifactCore> made = List.copyOf(cores);
        live = new Live(version, made);
        return made;
    }

    /** Called after each change to the artifacts {@link #cores} lists (made, named, disposed, forgotten). */
    private synchronized void artifactsChanged() {
        artifactsVersion++;
    }

    /** Tells every artifact that overrides {@link Artifact#agentLeft} that {@code agent} left, oldest first. */
    void tellAgentLeft(AgentId agent) {
        for (ArtifactCore core : byId.values()) {
            if (overridesAgentLeft(core.artifact().getClass())) {
                tellAgentLeft(core, agent);
            }
        }
    }

    private void tellAgentLeft(ArtifactCore core, AgentId agent) {
        core.lock().lock();
        try {
            if (!core.isDisposed()) {
                OpExecution.hook(core, null).runHook(AGENT_LEFT_HOOK, new Object[] {agent});
            }
        } catch (RuntimeException | Error e) {
            workspace.logger().warning(core.id().name(), "agentLeft(" + agent.name() + ") failed", e);
        } finally {
            core.lock().unlock();
        }
    }

    private static boolean overridesAgentLeft(Class<?> type) {
        for (Class<?> c = type; c != Artifact.class && c != null; c = c.getSuperclass()) {
            try {
                c.getDeclaredMethod("agentLeft", AgentId.class);
                return true;
            } catch (NoSuchMethodException e) {
                // look further up
            }
        }
        return false;
    }

    /** {@return the live artifact called {@code artifactName}'s id} */
    Optional<ArtifactId> lookup(String artifactName) {
        ArtifactCore core = byName.get(artifactName);
        return core == null ? Optional.empty() : Optional.of(core.id());
    }

    private static Method hook(String name, Class<?>... parameters) {
        try {
            return Artifact.class.getDeclaredMethod(name, parameters);
        } catch (NoSuchMethodException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
}
