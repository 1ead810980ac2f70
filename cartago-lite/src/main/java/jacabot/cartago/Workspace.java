package jacabot.cartago;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

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
 *
 * <p>Its parts: the artifacts it holds ({@link ArtifactRegistry}), the agents that joined and what
 * each focuses ({@link FocusBook}), and how operations are resolved ({@link OpResolver}) and run
 * ({@link Scheduler}); this class is the entry point that ties them together.
 */
public final class Workspace implements AutoCloseable {
    /** How operations run: on parallel carriers, or one step at a time inside {@link #runPending()}. */
    public enum Mode { THREADED, STEPPED }

    private final String name;
    private final Mode mode;
    private final ArtifactClock clock;
    private final CartagoLogger logger;
    private final PrintStream console;
    private final Scheduler scheduler;
    private final FocusBook agents;
    private final ArtifactRegistry registry;
    private final OpRoutes routes = new OpRoutes();
    private volatile boolean closed;
    /** Completed operations kept per agent and artifact; 0: the operation log is off. */
    private volatile int operationsKept;

    private Workspace(Builder b) {
        this.name = b.name;
        this.mode = b.mode;
        this.clock = b.clock;
        this.logger = b.logger;
        this.console = b.console;
        this.agents = new FocusBook(name);
        this.registry = new ArtifactRegistry(this, new ArtifactFactory(b.loader), agents);
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
            ArtifactCore core = registry.byId(focused.id());
            try {
                if (core != null) {
                    agents.stopFocus(agent, core);
                }
            } catch (OpFailedException disposedMeanwhile) {
                // Nothing to stop.
            }
        }
        ArtifactCore body = registry.byId(entry.body().id());
        if (body != null) {
            registry.dispose(body);
        }
        agents.remove(agent);
        registry.tellAgentLeft(agent);
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

    /** {@return where the agents' operations without a target went, while nothing changed} */
    OpRoutes routes() {
        return routes;
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
            return create(artifactName, registry.load(className), params, null);
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
            registry.dispose(registry.resolve(id));
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
        return registry.lookup(artifactName);
    }

    /**
     * {@return the live artifact object behind an id, for the Java program hosting the workspace
     * (e.g. a simulation runner collecting what an artifact produced); agents never get it}
     */
    public <T extends Artifact> Optional<T> artifactObject(ArtifactId id, Class<T> type) {
        ArtifactCore core = registry.byId(id.id());
        return core != null && type.isInstance(core.artifact()) ? Optional.of(type.cast(core.artifact())) : Optional.empty();
    }

    /** {@return the id of the live artifact numbered {@code id}} */
    public Optional<ArtifactId> artifact(int id) {
        ArtifactCore core = registry.byId(id);
        return core == null ? Optional.empty() : Optional.of(core.id());
    }

    /** {@return the live artifacts, oldest first} */
    public List<ArtifactId> artifacts() {
        List<ArtifactId> result = new ArrayList<>();
        for (ArtifactCore core : registry.all()) {
            result.add(core.id());
        }
        return result;
    }

    ArtifactId create(String artifactName, String className, Object[] params, AgentId creator) {
        return registry.create(artifactName, registry.load(className), params, creator);
    }

    ArtifactId create(String artifactName, Class<? extends Artifact> type, Object[] params, AgentId creator) {
        return registry.create(artifactName, type, params, creator);
    }

    /** Disposal asked by an agent: the workspace's own artifacts and bodies are refused. */
    void disposeFor(Object ref) {
        registry.disposeFor(ref);
    }

    /** {@return the live artifact an agent refers to: by ArtifactId, name or number} */
    ArtifactCore resolve(Object ref) {
        return registry.resolve(ref);
    }

    /** {@return live artifacts, oldest first (kept until an artifact comes or goes)} */
    List<ArtifactCore> cores() {
        return registry.cores();
    }

    boolean hasJoined(AgentId agent) {
        return agents.has(agent);
    }

    /**
     * {@return the operations agents may use on {@code id} (its usage interface, inherited ones
     * included), as name/arity, sorted; empty once it is disposed}
     */
    public List<String> operationsOf(ArtifactId id) {
        ArtifactCore core = registry.byId(id.id());
        return core == null ? List.of() : core.type().usageInterface();
    }

    /** {@return the agents observing {@code id}, in focus order} */
    public List<AgentId> observersOf(ArtifactId id) {
        ArtifactCore core = registry.byId(id.id());
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

    // ---- the operation log (a debugger's view; CArtAgO's loggers see every operation as it goes) ----

    /**
     * Keeps, from now on, the last {@code lastN} completed operations of each agent on each
     * artifact ({@link #operationLog}); 0, the default, keeps none. Off, it costs one volatile read
     * per operation; on, a clock reading and a record. It does not change how operations run.
     */
    public void recordOperations(int lastN) {
        if (lastN < 0) {
            throw new IllegalArgumentException("lastN must be 0 or more, not " + lastN);
        }
        operationsKept = lastN;
    }

    /** {@return whether {@link #recordOperations} is on} */
    public boolean recordsOperations() {
        return operationsKept > 0;
    }

    /** {@return the operations recorded on {@code id} so far, in the order they completed; empty once it is disposed} */
    public List<OperationRecord> operationLog(ArtifactId id) {
        ArtifactCore core = registry.byId(id.id());
        return core == null ? List.of() : core.operationLog();
    }

    int operationsKept() {
        return operationsKept;
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
        List<ArtifactCore> all = new ArrayList<>(registry.all());
        Collections.reverse(all);
        for (ArtifactCore core : all) {
            try {
                if (core.lock().tryLock(1, TimeUnit.SECONDS)) {
                    try {
                        if (!core.isDisposed()) {
                            registry.dispose(core);
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
