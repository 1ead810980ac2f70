package jacabot.cartago;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.function.BooleanSupplier;

/**
 * One running operation (or an {@code init}/{@code dispose} step, which may not suspend): its
 * target, arguments and caller, and the logic of its steps. A step holds the artifact from
 * {@link #enter} to {@link #exit}; {@code await*} commits, exits, waits through the
 * {@link Scheduler} and enters again. The thread running it is its <em>carrier</em>.
 */
final class OpExecution implements Runnable {
    private final ArtifactCore core;
    private final OpMethod op;
    private final Object[] args;
    private final AgentId agent;
    private final OpCallback callback;
    private final boolean suspendable;
    /** Per-execution slot of the scheduler (the stepped scheduler's turn). */
    final Scheduler.Slot slot = new Scheduler.Slot();
    private boolean holding;
    private OpExecution previous;
    private RuntimeException guardError;

    OpExecution(ArtifactCore core, OpMethod op, Object[] args, AgentId agent, OpCallback callback) {
        this.core = core;
        this.op = op;
        this.args = args;
        this.agent = agent;
        this.callback = callback;
        this.suspendable = op != null;
    }

    /** {@return a context for init/dispose hooks: a step that cannot suspend} */
    static OpExecution hook(ArtifactCore core, AgentId agent) {
        return new OpExecution(core, null, new Object[0], agent, null);
    }

    /** {@return whether this operation never waits ({@link AwaitAnalysis}): a stepped workspace runs it on its own thread} */
    boolean neverWaits() {
        return op != null && core.type().neverWaits(op);
    }

    AgentId agent() {
        return agent;
    }

    ArtifactCore core() {
        return core;
    }

    /** Runs the operation on its carrier, from its first step to its completion. */
    @Override
    public void run() {
        Scheduler scheduler = core.workspace().scheduler();
        int logged = core.workspace().operationsKept();
        long started = logged > 0 ? core.workspace().clock().nowMillis() : 0;
        OpOutcome outcome;
        try {
            enter(this::startable);
            checkStartable();
            invoke(op.method(), args);
            core.commit();
            outcome = new OpOutcome.Success(outputs());
        } catch (OpFailedException e) {
            outcome = e.failure();
        } catch (Throwable e) {
            outcome = OpOutcome.Failure.of("operation " + describe() + " failed: " + e, "exception",
                    e.getClass().getName(), String.valueOf(e.getMessage()));
            core.workspace().logger().warning(core.id().name(), "operation " + describe() + " threw", e);
        }
        if (holding) {
            if (!outcome.succeeded()) {
                core.rollback();
            }
            exit();
        }
        if (logged > 0) {
            core.recordOperation(new OperationRecord(started, core.workspace().clock().nowMillis(),
                    agent == null ? "" : agent.name(), op.name() + "/" + op.method().getParameterCount(), outcome.succeeded(),
                    outcome instanceof OpOutcome.Failure f ? (f.reasonFunctor() != null ? f.reasonFunctor() : f.message()) : ""), logged);
        }
        report(outcome);
        scheduler.finished(this);
    }

    /** Runs a non-suspendable hook ({@code init} or {@code dispose}) on this thread, atomically. */
    void runHook(Method method, Object[] hookArgs) {
        core.lock().lock();
        holding = true;
        previous = core.begin(this);
        try {
            invoke(method, hookArgs);
            core.commit();
        } catch (RuntimeException e) {
            core.rollback();
            throw e;
        } finally {
            core.end(previous);
            holding = false;
            core.lock().unlock();
        }
    }

    /** Starts an external session (a thread that is not an operation): holds the artifact. */
    static OpExecution beginSession(ArtifactCore core) {
        OpExecution session = new OpExecution(core, null, new Object[0], null, null);
        core.lock().lock();
        session.holding = true;
        session.previous = core.begin(session);
        return session;
    }

    /** Ends an external session: commits (or rolls back), wakes guards, releases the artifact. */
    void endSession(boolean success) {
        try {
            if (success) {
                core.commit();
            } else {
                core.rollback();
                core.changed().signalAll();
            }
        } finally {
            core.end(previous);
            holding = false;
            core.lock().unlock();
        }
    }

    private void invoke(Method method, Object[] values) {
        try {
            method.invoke(core.artifact(), values);
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException) {
                throw (RuntimeException) cause;
            }
            if (cause instanceof Error) {
                throw (Error) cause;
            }
            throw new OpFailedException(OpOutcome.Failure.of(
                    describe() + " failed: " + cause, "exception", cause.getClass().getName(), String.valueOf(cause.getMessage())));
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Waits until the step may run: the artifact is free and {@code ready} holds (or it is disposed). */
    private void enter(BooleanSupplier ready) {
        try {
            core.workspace().scheduler().enter(this, () -> core.isDisposed() || ready.getAsBoolean());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new OpFailedException("operation " + describe() + " interrupted: the workspace is closing", "interrupted");
        }
        holding = true;
        previous = core.begin(this);
    }

    private void exit() {
        core.end(previous);
        holding = false;
        core.workspace().scheduler().leave(this);
    }

    private boolean startable() {
        return op.guard() == null || guard(op.guard(), args);
    }

    private void checkStartable() {
        if (guardError != null) {
            throw guardError;
        }
        if (core.isDisposed()) {
            throw new OpFailedException("artifact " + core.id().name() + " was disposed", "artifact_disposed", core.id().name());
        }
    }

    /**
     * {@return whether a guard holds}; the caller holds the lock. A guard that throws counts as
     * holding, so that its step runs at once and fails with the guard's exception.
     */
    boolean guard(Method guard, Object[] values) {
        OpExecution outer = core.begin(this);
        try {
            return (Boolean) guard.invoke(core.artifact(), values);
        } catch (InvocationTargetException e) {
            guardError = e.getCause() instanceof RuntimeException ? (RuntimeException) e.getCause()
                    : new IllegalStateException("guard " + guard.getName() + " failed", e.getCause());
            return true;
        } catch (IllegalAccessException e) {
            guardError = new IllegalStateException(e);
            return true;
        } finally {
            core.end(outer);
        }
    }

    // ---- await primitives, called by the artifact inside this step ----

    void awaitGuard(Method guard, Object[] guardArgs) {
        suspend();
        enter(() -> guard(guard, guardArgs));
        checkStartable();
    }

    void awaitTime(long millis) {
        long deadline = core.workspace().clock().nowMillis() + Math.max(0, millis);
        suspend();
        try {
            core.workspace().scheduler().sleepUntil(this, deadline);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new OpFailedException("operation " + describe() + " interrupted: the workspace is closing", "interrupted");
        }
        enter(() -> true);
        checkStartable();
    }

    void awaitCommand(IBlockingCmd command) {
        suspend();
        RuntimeException error = null;
        try {
            core.workspace().scheduler().runBlocking(this, command);
        } catch (RuntimeException e) {
            error = e;
        }
        enter(() -> true);
        checkStartable();
        if (error != null) {
            throw error;
        }
    }

    /** Runs an operation of a linked artifact and waits for its outcome, as an await. */
    void awaitLinked(ArtifactCore target, String name, Object[] linkedArgs) {
        CompletableFuture<OpOutcome> done = new CompletableFuture<>();
        OpExecution linked = OpResolver.prepareFromArtifact(target, agent, name, linkedArgs, OpMethod.Kind.LINK, done::complete);
        suspend();
        Scheduler scheduler = core.workspace().scheduler();
        scheduler.launch(linked);
        try {
            scheduler.awaitDone(this, done);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new OpFailedException("operation " + describe() + " interrupted: the workspace is closing", "interrupted");
        }
        enter(() -> true);
        checkStartable();
        OpOutcome outcome = done.join();
        if (!outcome.succeeded()) {
            throw new OpFailedException((OpOutcome.Failure) outcome);
        }
    }

    private void suspend() {
        if (!suspendable) {
            throw new IllegalStateException("await is not allowed in init or dispose of " + core.id().name());
        }
        if (slot.inline) {
            throw new IllegalStateException("await is not allowed in " + describe() + ", which runs inline");
        }
        core.commit();
        exit();
    }

    private Map<Integer, Object> outputs() {
        // the caller's argument positions: a packed varargs array is spread out again
        List<Object> given = new ArrayList<>(Arrays.asList(args));
        if (op != null && op.method().isVarArgs() && !given.isEmpty() && given.get(given.size() - 1) instanceof Object[] packed) {
            given.remove(given.size() - 1);
            given.addAll(Arrays.asList(packed));
        }
        Map<Integer, Object> outputs = new LinkedHashMap<>();
        for (int i = 0; i < given.size(); i++) {
            if (given.get(i) instanceof OpFeedbackParam<?> out && out.isSet()) {
                outputs.put(i, out.get());
            }
        }
        return outputs;
    }

    private void report(OpOutcome outcome) {
        if (callback != null) {
            core.workspace().scheduler().deliver(() -> {
                try {
                    callback.completed(outcome);
                } catch (RuntimeException e) {
                    core.workspace().logger().warning(core.id().name(), "completion callback of " + describe() + " failed", e);
                }
            });
        } else if (!outcome.succeeded() && !core.workspace().isClosed()) {
            // an internal loop ended by the workspace closing is the normal end of a run, not news
            core.workspace().logger().warning(core.id().name(),
                    "internal operation " + describe() + " failed: " + ((OpOutcome.Failure) outcome).message(), null);
        }
    }

    String describe() {
        StringBuilder text = new StringBuilder(core.id().name()).append('.')
                .append(op == null ? "init" : op.name()).append('(');
        for (int i = 0; i < args.length; i++) {
            text.append(i == 0 ? "" : ",").append(Values.show(args[i]));
        }
        return text.append(')').toString();
    }
}
