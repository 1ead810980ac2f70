package jacabot.cartago;

import java.io.PrintStream;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A container of artifacts and the agents working with them, as in CArtAgO. It starts with the
 * artifacts {@code workspace} ({@link WorkspaceArtifact}) and {@code console}
 * ({@link ConsoleArtifact}); each agent that {@link #join joins} gets a body {@code body_<name>}
 * ({@link AgentBodyArtifact}) with {@code focus}/{@code stopFocus}.
 *
 * <p>Agents use artifacts only through {@link #execOp}, which resolves the target artifact and
 * the operation, converts the arguments and reports the outcome to a callback; they perceive
 * through the {@link ArtifactObserver} they joined with. See {@link Builder} for the two execution
 * modes (threaded, stepped) and the thread bound.
 */
public final class Workspace implements AutoCloseable {
    /** How operations run: on parallel carriers, or one step at a time inside {@link #runPending()}. */
    public enum Mode { THREADED, STEPPED }

    /** The workspace's own artifacts, which agents cannot dispose. */
    private static final Set<String> RESERVED = Set.of("workspace", "console");
    private static final Method DISPOSE_HOOK = hook("dispose");
    private static final Method AGENT_LEFT_HOOK = hook("agentLeft", AgentId.class);

    private final String name;
    private final Mode mode;
    private final ArtifactClock clock;
    private final CartagoLogger logger;
    private final PrintStream console;
    private final Scheduler scheduler;
    private final ArtifactFactory factory;
    private final AtomicInteger ids = new AtomicInteger();
    private final Set<String> names = ConcurrentHashMap.newKeySet();
    private final Map<String, ArtifactCore> byName = new ConcurrentHashMap<>();
    private final Map<Integer, ArtifactCore> byId = new ConcurrentSkipListMap<>();
    private final FocusBook agents;
    private volatile boolean closed;

    private Workspace(Builder b) {
        this.name = b.name;
        this.mode = b.mode;
        this.clock = b.clock;
        this.logger = b.logger;
        this.console = b.console;
        this.factory = new ArtifactFactory(b.loader);
        this.agents = new FocusBook(name);
        this.scheduler = mode == Mode.STEPPED
                ? new SteppedScheduler(name, b.maxThreads, clock, logger)
                : new ThreadedScheduler(name, b.maxThreads, clock, logger);
        create("workspace", WorkspaceArtifact.class, new Object[0], null);
        create("console", ConsoleArtifact.class, new Object[0], null);
        create("blackboard", TupleSpace.class, new Object[0], null);
    }

    /** {@return a builder for a workspace called {@code name}} */
    public static Builder builder(String name) {
        return new Builder(name);
    }

    // ---- agents ----

    /**
     * Lets an agent work in the workspace: creates its body {@code body_<name>} and registers the
     * observer through which it perceives. {@return the agent's id}
     *
     * @throws IllegalArgumentException if an agent of that name has joined already
     */
    public AgentId join(String agentName, ArtifactObserver observer) {
        Objects.requireNonNull(observer, "observer");
        AgentId agent = new AgentId(agentName);
        synchronized (agents) {
            if (agents.has(agent)) {
                throw new IllegalArgumentException("agent " + agentName + " has already joined workspace " + name);
            }
            ArtifactId body;
            try {
                body = create("body_" + agentName, AgentBodyArtifact.class, new Object[0], agent);
            } catch (OpFailedException e) {
                throw new IllegalArgumentException("agent " + agentName + " cannot join: " + e.getMessage(), e);
            }
            agents.add(agent, observer, body);
        }
        return agent;
    }

    /**
     * Ends an agent's work: it stops focusing everything, its body is disposed, and every artifact
     * that overrides {@link Artifact#agentLeft} is told, oldest first.
     */
    public void leave(AgentId agent) {
        FocusBook.Entry entry = agents.get(agent);
        if (entry == null) {
            return;
        }
        for (ArtifactId focused : entry.focused()) {
            ArtifactCore core = byId.get(focused.id());
            try {
                if (core != null) {
                    agents.stopFocus(agent, core);
                }
            } catch (OpFailedException disposedMeanwhile) {
                // Nothing to stop.
            }
        }
        ArtifactCore body = byId.get(entry.body().id());
        if (body != null) {
            dispose(body);
        }
        agents.remove(agent);
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
            logger.warning(core.id().name(), "agentLeft(" + agent.name() + ") failed", e);
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

    /** {@return the agents that have joined} */
    public List<AgentId> agents() {
        return agents.agents();
    }

    /** {@return the artifacts {@code agent} focuses, in focus order} */
    public List<ArtifactId> focusedBy(AgentId agent) {
        return agents.focusedBy(agent);
    }

    ArtifactObserver observerOf(AgentId agent) {
        return agents.observerOf(agent);
    }

    FocusBook focusBook() {
        return agents;
    }

    // ---- operations ----

    /**
     * Asks for the operation {@code operation(args...)} on behalf of {@code agent}; the outcome
     * comes later, exactly once, through {@code callback} (never on the calling thread in threaded
     * mode; at a {@link #runPending()} in stepped mode), except that a closed workspace fails the
     * call at once.
     *
     * <p>With {@link OpTarget#any()}, the artifact is the first one with an operation of that name
     * and arity among: the artifacts {@code agent} created, oldest first (its body included); then
     * those it focuses, in focus order; then every other one, oldest first (the bodies of other
     * agents excluded). Arguments convert as {@link ArgConverter} says; an output is passed as an
     * {@link OpFeedbackParam} the caller creates, whose value is also reported in
     * {@link OpOutcome.Success#outputs()}. Unknown agent, artifact or operation, wrong arity and
     * unconvertible arguments fail the call with a reason ({@code unknown_agent},
     * {@code unknown_artifact}, {@code unknown_operation}, {@code wrong_arity},
     * {@code bad_argument}).
     */
    public void execOp(AgentId agent, OpTarget target, String operation, Object[] args, OpCallback callback) {
        start(agent, target, operation, args, callback, false);
    }

    /**
     * Stepped mode, for a host feeding an artifact between two {@link #runPending()} calls (a
     * lockstep runner delivering a control step's readings): as {@link #execOp}, but when the
     * operation would be the next step anyway, it runs to its end now, on the calling thread,
     * sparing two thread hand-offs. Such an operation may not wait (an {@code await}, a false guard
     * make it fail). Its events and outcome are delivered at the next {@code runPending}, as usual.
     */
    public void execOpInline(AgentId agent, OpTarget target, String operation, Object[] args, OpCallback callback) {
        start(agent, target, operation, args, callback, true);
    }

    private void start(AgentId agent, OpTarget target, String operation, Object[] args, OpCallback callback,
            boolean inline) {
        Objects.requireNonNull(agent, "agent");
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(operation, "operation");
        Objects.requireNonNull(callback, "callback");
        Object[] values = args == null ? new Object[0] : args.clone();
        if (closed) {
            callback.completed(OpOutcome.Failure.of("workspace " + name + " is closed", "workspace_closed"));
            return;
        }
        try {
            OpExecution op = OpResolver.prepare(this, agent, target, operation, values, callback);
            if (!inline || !scheduler.runInline(op)) {
                scheduler.launch(op);
            }
        } catch (OpFailedException e) {
            scheduler.deliverLater(() -> callback.completed(e.failure()));
        } catch (RejectedExecutionException e) {
            callback.completed(OpOutcome.Failure.of("workspace " + name + " is closed", "workspace_closed"));
        }
    }

    /** Starts an internal operation of {@code core} for {@code agent}; see {@link Artifact#execInternalOp}. */
    void startInternal(ArtifactCore core, AgentId agent, String operation, Object[] args) {
        scheduler.launch(OpResolver.prepareFromArtifact(core, agent, operation, args, OpMethod.Kind.INTERNAL, null));
    }

    /** Starts a linked operation of {@code core}; see {@link Artifact#execLinkedOp}. */
    void startLinked(ArtifactCore core, AgentId agent, String operation, Object[] args, OpCallback callback) {
        scheduler.launch(OpResolver.prepareFromArtifact(core, agent, operation, args, OpMethod.Kind.LINK, callback));
    }

    /**
     * Runs the pending operation steps, one at a time on behalf of the calling thread, until none
     * is ready; delivers the resulting events and completions on the calling thread. Stepped mode
     * only; not reentrant. {@return the number of steps run}
     */
    public int runPending() {
        return scheduler.runPending();
    }

    // ---- artifacts ----

    /**
     * Creates an artifact from Java code (not on behalf of an agent), running its {@code init} on
     * the calling thread. {@return its id}
     *
     * @throws CartagoException for an unknown class, a duplicate name or a failing init
     */
    public ArtifactId createArtifact(String artifactName, String className, Object... params) throws CartagoException {
        try {
            return create(artifactName, factory.load(className), params, null);
        } catch (OpFailedException e) {
            throw new CartagoException(e.failure());
        }
    }

    /** Creates an artifact of {@code type} from Java code; see {@link #createArtifact(String, String, Object...)}. */
    public ArtifactId createArtifact(String artifactName, Class<? extends Artifact> type, Object... params)
            throws CartagoException {
        try {
            return create(artifactName, type, params, null);
        } catch (OpFailedException e) {
            throw new CartagoException(e.failure());
        }
    }

    /** Disposes an artifact from Java code. @throws CartagoException if it does not exist */
    public void disposeArtifact(ArtifactId id) throws CartagoException {
        try {
            dispose(resolve(id));
        } catch (OpFailedException e) {
            throw new CartagoException(e.failure());
        }
    }

    /** {@return whether {@link #close} has begun} */
    public boolean isClosed() {
        return closed;
    }

    /** {@return the id of the live artifact called {@code artifactName}} */
    public Optional<ArtifactId> lookup(String artifactName) {
        ArtifactCore core = byName.get(artifactName);
        return core == null ? Optional.empty() : Optional.of(core.id());
    }

    /**
     * {@return the live artifact object behind an id, for the Java program hosting the workspace
     * (e.g. a simulation runner collecting what an artifact produced); agents never get it}
     */
    public <T extends Artifact> Optional<T> artifactObject(ArtifactId id, Class<T> type) {
        ArtifactCore core = byId.get(id.id());
        return core != null && type.isInstance(core.artifact()) ? Optional.of(type.cast(core.artifact())) : Optional.empty();
    }

    /** {@return the id of the live artifact numbered {@code id}} */
    public Optional<ArtifactId> artifact(int id) {
        ArtifactCore core = byId.get(id);
        return core == null ? Optional.empty() : Optional.of(core.id());
    }

    /** {@return the live artifacts, oldest first} */
    public List<ArtifactId> artifacts() {
        List<ArtifactId> result = new ArrayList<>();
        for (ArtifactCore core : byId.values()) {
            result.add(core.id());
        }
        return result;
    }

    ArtifactId create(String artifactName, String className, Object[] params, AgentId creator) {
        return create(artifactName, factory.load(className), params, creator);
    }

    ArtifactId create(String artifactName, Class<? extends Artifact> type, Object[] params, AgentId creator) {
        if (closed) {
            throw new OpFailedException("workspace " + name + " is closed", "workspace_closed");
        }
        if (artifactName == null || artifactName.isEmpty()) {
            throw new OpFailedException("an artifact needs a non-empty name", "bad_argument", 1);
        }
        ArtifactType artifactType = factory.typeOf(type);
        if (!names.add(artifactName)) {
            throw new OpFailedException("an artifact called " + artifactName + " already exists in workspace " + name,
                    "duplicate_name", artifactName);
        }
        try {
            Artifact artifact = factory.instantiate(type);
            ArtifactId id = new ArtifactId(ids.incrementAndGet(), artifactName, type.getName(), name, creator);
            ArtifactCore core = new ArtifactCore(artifact, id, artifactType, this);
            artifact.bind(core);
            registerDuringInit(core);
            try {
                factory.init(core, params);
            } catch (RuntimeException e) {
                unregister(core);
                core.lock().lock();
                try {
                    core.markDisposed();
                } finally {
                    core.lock().unlock();
                }
                throw e;
            }
            byName.put(artifactName, core);
            return id;
        } catch (RuntimeException e) {
            names.remove(artifactName);
            throw e;
        }
    }

    /** Internal operations started by {@code init} need the artifact findable by id only. */
    private void registerDuringInit(ArtifactCore core) {
        byId.put(core.id().id(), core);
    }

    private void unregister(ArtifactCore core) {
        byId.remove(core.id().id());
        byName.remove(core.id().name(), core);
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
                logger.warning(core.id().name(), "dispose() failed", e);
            }
            agents.forget(core.id(), core.markDisposed());
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
            throw new OpFailedException("no artifact " + ref + " in workspace " + name, "unknown_artifact", String.valueOf(ref));
        }
        return core;
    }

    /** {@return live artifacts, oldest first} */
    List<ArtifactCore> cores() {
        List<ArtifactCore> live = new ArrayList<>();
        for (ArtifactCore core : byId.values()) {
            if (!core.isDisposed() && byName.get(core.id().name()) == core) {
                live.add(core);
            }
        }
        return live;
    }

    boolean hasJoined(AgentId agent) {
        return agents.has(agent);
    }

    /**
     * {@return the operations agents may use on {@code id} (its usage interface, inherited ones
     * included), as name/arity, sorted; empty once it is disposed}
     */
    public List<String> operationsOf(ArtifactId id) {
        ArtifactCore core = byId.get(id.id());
        return core == null ? List.of() : core.type().usageInterface();
    }

    /** {@return the agents observing {@code id}, in focus order} */
    public List<AgentId> observersOf(ArtifactId id) {
        ArtifactCore core = byId.get(id.id());
        if (core == null) {
            return List.of();
        }
        core.lock().lock();
        try {
            return core.observers();
        } finally {
            core.lock().unlock();
        }
    }

    // ---- configuration ----

    /** {@return the workspace's name} */
    public String getName() {
        return name;
    }

    /** {@return the execution mode} */
    public Mode mode() {
        return mode;
    }

    /** {@return the clock of {@code await_time}} */
    public ArtifactClock clock() {
        return clock;
    }

    CartagoLogger logger() {
        return logger;
    }

    PrintStream console() {
        return console;
    }

    Scheduler scheduler() {
        return scheduler;
    }

    /**
     * Disposes every artifact (running their {@code dispose()} hooks, which should release I/O
     * that operations are blocked on), then stops the carrier threads; suspended operations fail.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        List<ArtifactCore> all = new ArrayList<>(byId.values());
        Collections.reverse(all);
        for (ArtifactCore core : all) {
            try {
                if (core.lock().tryLock(1, TimeUnit.SECONDS)) {
                    try {
                        if (!core.isDisposed()) {
                            dispose(core);
                        }
                    } finally {
                        core.lock().unlock();
                    }
                } else {
                    logger.warning(name, "artifact " + core.id().name() + " is busy; closing without its dispose()", null);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        scheduler.close();
    }

    private static Method hook(String name, Class<?>... parameters) {
        try {
            return Artifact.class.getDeclaredMethod(name, parameters);
        } catch (NoSuchMethodException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    @Override
    public String toString() {
        return "workspace " + name + " (" + mode.name().toLowerCase(Locale.ROOT) + ")";
    }

    /**
     * Configures a workspace. Defaults: threaded mode, the wall clock, at most 64 operation
     * threads, the platform logger, {@code System.out} as console, the class loader of this class.
     */
    public static final class Builder {
        private final String name;
        private Mode mode = Mode.THREADED;
        private ArtifactClock clock = new WallClock();
        private CartagoLogger logger = CartagoLogger.platform();
        private PrintStream console = System.out;
        private ClassLoader loader = Workspace.class.getClassLoader();
        private int maxThreads = 64;

        private Builder(String name) {
            this.name = Objects.requireNonNull(name, "name");
        }

        /** Operations run on parallel carriers (the default). */
        public Builder threaded() {
            this.mode = Mode.THREADED;
            return this;
        }

        /** Operations run one step at a time, only inside {@link Workspace#runPending()}. */
        public Builder stepped() {
            this.mode = Mode.STEPPED;
            return this;
        }

        /** Sets the clock of {@code await_time}, e.g. a {@link SimulatedClock}. */
        public Builder clock(ArtifactClock value) {
            this.clock = Objects.requireNonNull(value, "clock");
            return this;
        }

        /** Sets where the runtime and {@link Artifact#log(String)} write. */
        public Builder logger(CartagoLogger value) {
            this.logger = Objects.requireNonNull(value, "logger");
            return this;
        }

        /** Sets where the {@code console} artifact prints. */
        public Builder console(PrintStream value) {
            this.console = Objects.requireNonNull(value, "console");
            return this;
        }

        /** Sets the class loader of {@code makeArtifact}'s class names. */
        public Builder classLoader(ClassLoader value) {
            this.loader = Objects.requireNonNull(value, "classLoader");
            return this;
        }

        /**
         * Bounds the carrier threads, i.e. the operations in progress at once (running or suspended
         * in {@code await*}); more operations queue until one ends.
         */
        public Builder maxOperationThreads(int value) {
            if (value < 1) {
                throw new IllegalArgumentException("maxOperationThreads must be at least 1, not " + value);
            }
            this.maxThreads = value;
            return this;
        }

        /** {@return the workspace} */
        public Workspace build() {
            return new Workspace(this);
        }
    }
}
