package jacabot.agent.semantics;

import jacabot.agent.syntax.Term;
import java.util.Iterator;

/**
 * An internal action such as {@code .print} or {@code .member}. {@link #execute} returns a
 * {@link Boolean} or an {@code Iterator<Unifier>} of solutions (for backtracking actions).
 */
public interface InternalAction {
    Object execute(Agent agent, Unifier un, Term[] args) throws IaException;

    /**
     * Solutions that a proof may also take by having each made in its own unifier, which it has
     * just cut back to the bindings the action was given: a {@code for} over {@code .range} then
     * makes no unifier per turn.
     */
    interface Solutions extends Iterator<Unifier> {
        /** {@return whether there is another solution; its bindings are then added to {@code w}} */
        boolean nextInto(Unifier w);
    }

    /** {@return whether the intention must not be requeued after the action (e.g. {@code .wait})} */
    default boolean suspendsIntention() {
        return false;
    }

    /**
     * {@return whether arguments are given with the unifier applied (control structures say no)}
     * Arguments not applied come in an array shared by the calls for one formula: not to be changed.
     */
    default boolean appliesArguments() {
        return true;
    }

    default int minArgs() {
        return 0;
    }

    default int maxArgs() {
        return Integer.MAX_VALUE;
    }
}
