package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;

/** Told of a goal that failed with no failure plan to handle it; runs on the agent's thread. */
@FunctionalInterface
public interface UnhandledFailureListener {
    /**
     * {@code failure} is the failed goal with its failure annotations ({@code error}, ...);
     * {@code root} the first goal of its intention, which is dropped.
     */
    void failureUnhandled(Literal failure, Literal root);
}
