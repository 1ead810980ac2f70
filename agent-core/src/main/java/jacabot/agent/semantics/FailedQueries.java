package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Rule queries of plan contexts known to have no solution while the belief base is unchanged (one
 * agent's, used on its thread). A robot's agent tries several plans for one goal at each control
 * step whose contexts begin with the same rule ({@code arcTurn(G)} in three plans of {@code +!balance}):
 * when it fails, it failed for each of them (the three were half the time spent in contexts in
 * experiment 4). A proof consults the belief base, relations and pure arithmetic only, unless it runs
 * an internal action, {@code math.random}, {@code system.time}, a function defined by rules or a
 * warning ({@link Solver#sideEffect}): so a query of the same literal (its variables renamed alike)
 * that ran none of these fails again until the belief base changes ({@link BeliefBase#changes}). A
 * failed proof leaves nothing but the fresh variables' numbers it took, so a query answered here
 * takes as many ({@link Agent#retakeVars}), and later variables are numbered as they were.
 */
final class FailedQueries {
    private final Map<Key, long[]> failed = new HashMap<>();
    private long changesSeen = -1;
    /** Queries answered here so far (for tests). */
    private long answered;

    /**
     * {@return the key of a query made of a predicate and arguments that are ground or variables, its
     * variables numbered by first occurrence; null for any other (annotations, structures with
     * variables)}
     */
    static Key key(Literal q, Unifier w) {
        if (!q.annots().isEmpty() || q.tail() != null || q.ns() != null) {
            return null;
        }
        int n = q.arity();
        Object[] args = n == 0 ? NO_ARGS : new Object[n];
        List<Var> vars = null;
        for (int i = 0; i < n; i++) {
            Term a = w.deref(q.arg(i));
            if (a instanceof Var v) {
                if (vars == null) {
                    vars = new ArrayList<>(2);
                }
                int k = vars.indexOf(v);
                if (k < 0) {
                    k = vars.size();
                    vars.add(v);
                }
                args[i] = k; // an Integer: no term equals it
            } else if (a.isGround()) {
                args[i] = a;
            } else {
                return null;
            }
        }
        return new Key(q.functor(), q.negated(), args);
    }

    private static final Object[] NO_ARGS = new Object[0];

    /**
     * A query's key: predicate, negation, and per argument the ground term or its variable's number
     * (one object and its array, where a list of boxed parts took more and hashed through an iterator).
     */
    static final class Key {
        private final String functor;
        private final boolean negated;
        private final Object[] args;
        private final int hash;

        Key(String functor, boolean negated, Object[] args) {
            this.functor = functor;
            this.negated = negated;
            this.args = args;
            this.hash = (functor.hashCode() * 31 + Arrays.hashCode(args)) * 31 + Boolean.hashCode(negated);
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && k.hash == hash && k.negated == negated && k.functor.equals(functor)
                    && Arrays.equals(k.args, args);
        }

        @Override
        public int hashCode() {
            return hash;
        }
    }

    /** {@return whether the query is known to fail now}; if so, its fresh variables' numbers are taken */
    boolean fails(Key key, Agent agent) {
        long[] taken = current(agent).get(key);
        if (taken == null) {
            return false;
        }
        agent.retakeVars(taken[0], taken[1]);
        answered++;
        return true;
    }

    /** The query failed, taking {@code fresh} and {@code internal} variables' numbers. */
    void failed(Key key, Agent agent, long fresh, long internal) {
        current(agent).put(key, new long[] {fresh, internal});
    }

    long answered() {
        return answered;
    }

    private Map<Key, long[]> current(Agent agent) {
        long changes = agent.beliefBase().changes();
        if (changes != changesSeen) {
            failed.clear();
            changesSeen = changes;
        }
        return failed;
    }
}
