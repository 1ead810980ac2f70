package jacabot.cartago;

import java.lang.reflect.Method;
import java.util.List;

/**
 * The base class of artifacts, with CArtAgO's API: subclass it, give it a no-argument
 * constructor, an optional {@code init(...)} (the constructor agents call, matched by number and
 * conversion of arguments) and {@link OPERATION}-annotated methods. The protected primitives may
 * only be used inside the artifact's own operations, guards and {@code init}; they throw
 * {@link IllegalStateException} anywhere else.
 *
 * <p>Semantics: one operation step runs at a time in an artifact. Property changes stay private to
 * the step until a commit point: the end of the operation, {@link #signal}, {@link #commit()} and
 * every {@code await*}, which also releases the artifact until the awaited condition holds.
 * {@link #failed} (or an exception) ends the operation and rolls back the changes made since the
 * last commit point, including removals.
 */
public abstract class Artifact {
    private ArtifactCore core;

    /** Connects the artifact to its runtime, before {@code init}. */
    final void bind(ArtifactCore core) {
        this.core = core;
    }

    final ArtifactCore core() {
        return core;
    }

    /** {@return the artifact's id} */
    public final ArtifactId getId() {
        return core.id();
    }

    /** {@return the agent that created the artifact, or null for the workspace's own} */
    protected final AgentId getCreatorId() {
        return core.id().creator();
    }

    /** {@return the agent whose operation (or internal operation started by it) is running} */
    protected final AgentId getCurrentOpAgentId() {
        return core.current().agent();
    }

    // ---- observable properties ----

    /** Defines the observable property {@code name(values...)}; several may share a name, as in CArtAgO. */
    protected final ObsProperty defineObsProperty(String name, Object... values) {
        return core.properties().define(name, values);
    }

    /** {@return the observable property called {@code name}, or null} */
    protected final ObsProperty getObsProperty(String name) {
        return core.properties().get(name);
    }

    /** {@return whether an observable property called {@code name} exists} */
    protected final boolean hasObsProperty(String name) {
        return core.properties().has(name);
    }

    /** Removes the observable property called {@code name}, which must exist. */
    protected final void removeObsProperty(String name) {
        core.properties().remove(name);
    }

    /** Replaces all values of the existing observable property {@code name}. */
    protected final void updateObsProperty(String name, Object... values) {
        ObsProperty property = getObsProperty(name);
        if (property == null) {
            throw new IllegalArgumentException("no observable property " + name + " in " + core.id().name());
        }
        property.updateValues(values);
    }

    // ---- signals, failure, logging ----

    /** Commits, then signals {@code type(args...)} to every agent focusing the artifact. */
    protected final void signal(String type, Object... args) {
        core.current();
        core.signal(null, type, Values.listOf(args));
    }

    /** Commits, then signals {@code type(args...)} to {@code agent} alone (focusing or not). */
    protected final void signal(AgentId agent, String type, Object... args) {
        core.current();
        core.signal(agent, type, Values.listOf(args));
    }

    /** Publishes the pending property changes now, without ending the step. */
    protected final void commit() {
        core.current();
        core.commit();
    }

    /** Fails the running operation with {@code message}; uncommitted changes are rolled back. */
    protected final void failed(String message) {
        core.current();
        throw new OpFailedException(new OpOutcome.Failure(message, null, List.of()));
    }

    /**
     * Fails the running operation with {@code message} and the reason term
     * {@code reason(args...)}; uncommitted changes are rolled back.
     */
    protected final void failed(String message, String reason, Object... args) {
        core.current();
        throw new OpFailedException(new OpOutcome.Failure(message, reason, Values.listOf(args)));
    }

    /** Writes {@code message} to the workspace's logger, tagged with the artifact's name. */
    protected final void log(String message) {
        core.workspace().logger().info(core.id().name(), message);
    }

    // ---- suspension and internal operations ----

    /**
     * Commits, releases the artifact, runs {@code command} (blocking I/O, which must not touch
     * the artifact) and takes the artifact back; an exception of the command is rethrown here.
     */
    protected final void await(IBlockingCmd command) {
        core.current().awaitCommand(command);
    }

    /** Commits, releases the artifact and resumes once the guard {@code guardName(args...)} holds. */
    protected final void await(String guardName, Object... args) {
        OpExecution step = core.current();
        List<Method> guards = core.type().guards(guardName, args.length);
        if (guards.isEmpty()) {
            throw new IllegalArgumentException("no @GUARD " + guardName + " with " + args.length + " parameter(s) in "
                    + getClass().getName());
        }
        Object[] converted;
        try {
            converted = ArgConverter.convertAll(guards.get(0), args);
        } catch (ArgConverter.Mismatch e) {
            throw new IllegalArgumentException("guard " + guardName + ": " + e.getMessage(), e);
        }
        step.awaitGuard(guards.get(0), converted);
    }

    /** {@return the workspace's clock (the wall clock, or simulated time)} */
    protected final ArtifactClock getClock() {
        return core.workspace().clock();
    }

    /** Commits, releases the artifact and resumes after {@code millis} of the workspace's clock. */
    protected final void await_time(long millis) {
        core.current().awaitTime(millis);
    }

    /**
     * Starts the (internal) operation {@code name(args...)} of this artifact as a separate
     * process, which runs once this step releases the artifact; it acts for the same agent.
     */
    protected final void execInternalOp(String name, Object... args) {
        OpExecution step = core.current();
        core.workspace().startInternal(core, step.agent(), name, args);
    }

    /**
     * Runs the operation {@code name(args...)} of the artifact {@code target} ({@link LINK}
     * operations first, then ordinary ones) for the same agent, and waits for it: like an
     * {@code await}, this commits and releases this artifact meanwhile. Outputs given as
     * {@link OpFeedbackParam}s are set when it returns; its failure fails this operation too.
     */
    protected final void execLinkedOp(ArtifactId target, String name, Object... args) {
        OpExecution step = core.current();
        step.awaitLinked(core.workspace().resolve(target), name, args);
    }

    /**
     * Runs {@code name(args...)} on every artifact linked to the out port {@code outPort}, one
     * after the other, as {@link #execLinkedOp(ArtifactId, String, Object...)} does.
     *
     * @throws OperationException for an undeclared port, a port without links, or a failed operation
     */
    protected final void execLinkedOp(String outPort, String name, Object... args) {
        OpExecution step = core.current();
        List<ArtifactId> targets = core.linked(outPort);
        if (targets == null) {
            throw new OperationException(OpOutcome.Failure.of("no out port " + outPort + " in " + core.id().name(),
                    "unknown_port", outPort));
        }
        if (targets.isEmpty()) {
            throw new OperationException(OpOutcome.Failure.of("no artifact linked to out port " + outPort + " of "
                    + core.id().name(), "not_linked", outPort));
        }
        for (ArtifactId target : targets) {
            try {
                step.awaitLinked(core.workspace().resolve(target), name, args);
            } catch (OperationException e) {
                throw e;
            } catch (OpFailedException e) {
                throw new OperationException(e.failure());
            }
        }
    }

    /** {@return whether an artifact is linked to the out port {@code outPort}} */
    protected final boolean isLinked(String outPort) {
        core.current();
        List<ArtifactId> targets = core.linked(outPort);
        return targets != null && !targets.isEmpty();
    }

    // ---- other artifacts, from inside this one ----

    /**
     * Makes an artifact for the agent of the running operation, passing {@code config}'s
     * parameters to its {@code init} (which runs now, on this thread). {@return its id}
     *
     * @throws OperationException with the reason of {@code makeArtifact} (unknown_class, ...)
     */
    protected final ArtifactId makeArtifact(String name, String className, ArtifactConfig config) {
        OpExecution step = core.current();
        try {
            return core.workspace().create(name, className, (config == null ? ArtifactConfig.DEFAULT_CONFIG : config).getParams(),
                    step.agent());
        } catch (OperationException e) {
            throw e;
        } catch (OpFailedException e) {
            throw new OperationException(e.failure());
        }
    }

    /** {@return the id of the artifact called {@code name}} @throws OperationException if there is none */
    protected final ArtifactId lookupArtifact(String name) {
        core.current();
        return core.workspace().lookup(name).orElseThrow(() -> new OperationException(
                OpOutcome.Failure.of("artifact " + name + " not found", "unknown_artifact", name)));
    }

    /** Disposes another artifact. @throws OperationException as {@code disposeArtifact} fails */
    protected final void dispose(ArtifactId id) {
        core.current();
        try {
            core.workspace().disposeFor(id);
        } catch (OperationException e) {
            throw e;
        } catch (OpFailedException e) {
            throw new OperationException(e.failure());
        }
    }

    /** {@return the body artifact of the agent whose operation is running (null for none)} */
    protected final ArtifactId getCurrentOpAgentBody() {
        AgentId agent = core.current().agent();
        return agent == null ? null : core.workspace().lookup("body_" + agent.name()).orElse(null);
    }

    /**
     * Waits {@code millis} of wall time holding the artifact, as CArtAgO's {@code delay} does (no
     * other operation of this artifact runs meanwhile; {@link #await_time} releases it).
     */
    protected final void delay(long millis) {
        core.current();
        try {
            Thread.sleep(Math.max(0, millis));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new OpFailedException("interrupted: the workspace is closing", "interrupted");
        }
    }

    // ---- observable properties by template (several may share a name) ----

    /** {@return the first property {@code name} whose values match {@code template} (null matches anything), or null} */
    protected final ObsProperty getObsPropertyByTemplate(String name, Object... template) {
        return core.properties().getByTemplate(name, template);
    }

    protected final boolean hasObsPropertyByTemplate(String name, Object... template) {
        return getObsPropertyByTemplate(name, template) != null;
    }

    /** Removes the first property {@code name} matching {@code template}, which must exist. */
    protected final void removeObsPropertyByTemplate(String name, Object... template) {
        core.properties().removeByTemplate(name, template);
    }

    // ---- external sessions: a thread that is not an operation (a GUI, a timer) uses the artifact ----

    /**
     * Takes the artifact for the calling thread, waiting for the running step to end. Between
     * this and {@link #endExternalSession} the primitives work as inside an operation.
     */
    protected final void beginExternalSession() {
        OpExecution.beginSession(core);
    }

    /** Commits ({@code success}) or rolls back the session's changes and releases the artifact. */
    protected final void endExternalSession(boolean success) {
        OpExecution session = core.current();
        session.endSession(success);
    }

    /**
     * Called when the artifact is disposed (by {@code disposeArtifact} or the workspace closing),
     * holding the artifact; release resources here. Operations suspended in the artifact fail
     * when they resume. Does nothing by default.
     */
    protected void dispose() {
    }

    /**
     * Called when {@code agent} leaves the workspace ({@link Workspace#leave}: its process ended or it
     * was stopped), after its focuses ended, holding the artifact as an operation does: let go of what
     * the agent held here (a claim, a place in a queue), so that no other agent waits for it for ever.
     * Changes are committed when it returns and rolled back if it throws. Does nothing by default.
     * Not in CArtAgO, where an artifact never learns that an agent has gone.
     */
    protected void agentLeft(AgentId agent) {
    }

    @Override
    public String toString() {
        return core == null ? getClass().getSimpleName() : core.id().name();
    }
}
