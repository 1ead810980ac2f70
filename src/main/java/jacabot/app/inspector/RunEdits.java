package jacabot.app.inspector;

/**
 * What the inspector's page may do with the run's agent program: start a "what if" (the run
 * again up to an instant, then the edited plans) and, for a live run, reload the edited plans into
 * the running agent (as Jason's hot reload of plans: beliefs and intentions stay): a lockstep run
 * when the debugger halts it, a real-time run at the start of the agent's next reasoning cycle.
 * Implemented where runs are made; the page only sends text.
 */
public interface RunEdits {
    /** When a reload reaches the running agent. */
    enum Reload {
        /** never: a recorded run */
        NONE,
        /** a live lockstep run, while the debugger halts it */
        AT_HALT,
        /** a live real-time run, at the start of the agent's next reasoning cycle */
        AT_NEXT_CYCLE
    }

    /** {@return the agent's own program text, where the page's editor starts} */
    String source();

    /**
     * Runs a what-if for {@code job} with {@code program} as the edited agent; blocks until it
     * ends (the inspector calls it on a thread of its own) and reports into the job.
     *
     * @throws IllegalArgumentException with the program's error (file:line:col) when it does not parse
     */
    void whatIf(WhatIfJob job, String program) throws Exception;

    /** {@return why this run cannot start a what-if, or null when it can (the page says it when asked for one)} */
    default String whatIfRefusal() {
        return null;
    }

    /** {@return when {@link #reload} reaches the running agent} */
    default Reload reloads() {
        return Reload.NONE;
    }

    /**
     * Replaces the live run's plans by {@code program}'s, on the agent's own thread; blocks until
     * they are. {@return what happened, for the page (e.g. the simulated time it was applied at)}
     *
     * @throws IllegalStateException when the run is recorded, not halted (lockstep) or no longer reasoning
     * @throws IllegalArgumentException when the program does not parse (its file:line:col); nothing changed
     */
    default String reload(String program) throws Exception {
        throw new IllegalStateException("a recorded run cannot change: start a what-if from an instant instead");
    }
}
