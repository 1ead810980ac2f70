package jacabot.app.inspector;

/**
 * What the inspector's page may do with the run's agent program: start a "what if" (the run
 * again up to an instant, then the edited plans) and, for a live lockstep run halted by the
 * debugger, reload the edited plans into the running agent (as Jason's hot reload of plans:
 * beliefs and intentions stay). Implemented where runs are made; the page only sends text.
 */
public interface RunEdits {
    /** {@return the agent's own program text, where the page's editor starts} */
    String source();

    /**
     * Runs a what-if for {@code job} with {@code program} as the edited agent; blocks until it
     * ends (the inspector calls it on a thread of its own) and reports into the job.
     *
     * @throws IllegalArgumentException with the program's error (file:line:col) when it does not parse
     */
    void whatIf(WhatIfJob job, String program) throws Exception;

    /**
     * Replaces the halted live run's plans by {@code program}'s, on the run's thread.
     *
     * @throws IllegalStateException when the run is recorded, or not halted
     * @throws IllegalArgumentException when the program does not parse
     */
    default void reload(String program) throws Exception {
        throw new IllegalStateException("a recorded run cannot change: start a what-if from an instant instead");
    }
}
