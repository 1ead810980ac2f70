package jacabot.agent.semantics;

import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.Term;

/**
 * Goals still to prove, first first, each with the depth of rules it comes from: a linked list that
 * a {@link Proof}'s choice points share. A rule's body is renamed goal by goal as the proof reaches
 * each (a body that fails at its third goal copies three goals, not all of them), and a node keeps
 * what it made: backtracking that comes back to a node finds its goal renamed, or the nodes of its
 * conjunction's or disjunction's parts. The renaming is a function of the term alone, so the goals
 * are those a body renamed whole would give.
 */
final class Goals {
    private final Term goal;
    final Goals next;
    final int depth;
    /** The renaming of the rule this goal comes from, not yet applied to {@link #goal}; null if none. */
    private final Solver.Renaming renaming;
    private Term renamed;
    /** A renamed conjunction's first part, or a renamed disjunction's left and right parts, once made. */
    private Goals first, second;

    Goals(Term goal, Goals next, int depth, Solver.Renaming renaming) {
        this.goal = goal;
        this.next = next;
        this.depth = depth;
        this.renaming = renaming;
    }

    /** {@return the goal as a proof steps it: renamed, unless it is a conjunction or disjunction (its parts are)} */
    Term goal() {
        if (renaming == null || goal instanceof LogExpr e && e.op() != LogExpr.Op.NOT) {
            return goal;
        }
        Term r = renamed;
        if (r == null) {
            r = renaming.map(goal);
            renamed = r;
        }
        return r;
    }

    /**
     * {@return the goals of conjunction {@code e}: its left part, its right part, then {@link #next}}
     * {@code e} is this node's goal, or the value of a variable the goal is, which is renamed no further
     * and may differ at the next visit.
     */
    Goals conjunction(LogExpr e) {
        Solver.Renaming rn = e == goal ? renaming : null;
        Goals g = rn == null ? null : first;
        if (g == null) {
            g = new Goals(e.left(), new Goals(e.right(), next, depth, rn), depth, rn);
            if (rn != null) {
                first = g;
            }
        }
        return g;
    }

    /** {@return the goals of disjunction {@code e}'s left or right part, then {@link #next}} ({@code e} as in {@link #conjunction}) */
    Goals disjunct(LogExpr e, boolean right) {
        Solver.Renaming rn = e == goal ? renaming : null;
        Goals g = rn == null ? null : right ? second : first;
        if (g == null) {
            g = new Goals(right ? e.right() : e.left(), next, depth, rn);
            if (rn != null) {
                if (right) {
                    second = g;
                } else {
                    first = g;
                }
            }
        }
        return g;
    }
}
