package jacabot.agent.semantics;

import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;

/**
 * The proof of one formula, solution after solution in Jason's order (depth first, left to right,
 * beliefs and rules in belief-base order). It works on one unifier whose bindings are a trail: a
 * resolution step only appends bindings, and backtracking cuts them back to a choice point's mark.
 * The goals still to prove are a linked list shared by the choice points, so a step copies neither
 * bindings nor goals. A choice point is popped before its last alternative is tried, so a
 * recursive clause called last (as in {@code ancestor/2}) leaves nothing behind: memory follows the
 * live proof, and time the number of steps.
 */
final class Proof {
    /** The deepest nesting of rules a proof may reach (system property jacabot.maxProofDepth). */
    static final int MAX_DEPTH = Integer.getInteger("jacabot.maxProofDepth", 100_000);

    /** A too deep proof: handled where the JVM's stack overflow was (error(stack_overflow)). */
    static final class TooDeep extends StackOverflowError {
        private static final long serialVersionUID = 1L;

        TooDeep() {
            super("a proof nested more than " + MAX_DEPTH + " rules (-Djacabot.maxProofDepth)");
        }
    }

    /** A choice point: the trail mark and the goals after the choice. */
    private abstract static class Choice {
        final int mark;
        final Goals rest;

        Choice(int mark, Goals rest) {
            this.mark = mark;
            this.rest = rest;
        }

        /**
         * Takes the next alternative (bindings are back at the mark). {@return whether one
         * succeeded}; a choice with no alternative left has popped itself
         */
        abstract boolean resume(Proof p);
    }

    private final Solver solver;
    private final Unifier w;
    private final int base;
    private final Term formula;
    private final int startDepth;
    /** The choice points, the last on top: an array made at the first (a loop's condition often has none). */
    private Choice[] choices = NO_CHOICES;
    private int nChoices;
    private static final Choice[] NO_CHOICES = new Choice[0];
    private Goals goals;
    private boolean started;
    /** Whether the first literal this proof steps may be a query known to fail ({@link FailedQueries}), and its fence. */
    private boolean remember;
    private Fence fence;
    private List<Var> formulaVars;
    /** The current answer's pairs (variable, value), the first of them in use; see {@link #answer}. */
    private Object[] answerPairs = NO_PAIRS;
    private static final Object[] NO_PAIRS = new Object[0];

    /** A proof that works in {@code w}, beginning with its bindings as they are now. */
    Proof(Solver solver, Term formula, Unifier w, int depth) {
        this.solver = solver;
        this.w = w;
        this.base = w.size();
        this.formula = formula;
        this.startDepth = depth;
    }

    /**
     * Moves to the next solution, whose bindings are then in the unifier. {@return false when
     * there is none left} (the unifier is then as it was)
     */
    boolean next() {
        boolean found;
        if (!started) {
            started = true;
            goals = new Goals(formula, null, startDepth, null);
            found = run();
        } else {
            found = backtrack() && run();
        }
        if (!found) {
            w.undoTo(base);
        }
        return found;
    }

    /** Keeps only the current solution's answer in the unifier (see {@link #answer}). */
    void keepAnswer() {
        int n = answer();
        w.undoTo(base);
        w.rebind(answerPairs, n);
    }

    /** Gives {@code into} the current solution: the first bindings and the answer. */
    void solutionInto(Unifier into) {
        int n = answer();
        into.setFromPrefix(w, base, answerPairs, n);
    }

    /** {@return the current solution as a new unifier: the first bindings and the answer} */
    Unifier solution() {
        int n = answer();
        return w.prefixWith(base, answerPairs, n);
    }

    /**
     * The bindings the current solution gives the formula's variables, each to its final value
     * (chains through renamed rule variables are cut short). What only the rules' own variables
     * were bound to is left out, as Jason's rule solutions leave it out, so a solution's size
     * is the size of the answer, not of the proof. {@return the number of array slots used in
     * {@link #answerPairs} (two per binding)}
     */
    private int answer() {
        if (formulaVars == null) {
            formulaVars = solver.varsOf(formula);
        }
        // in the formula's order, then in the order the values name them ("more", made only when
        // a value names variables)
        List<Var> vars = formulaVars;
        ArrayList<Var> more = null;
        HashSet<Var> seen = null;
        // in an array of the proof's own, used up before the next answer (a loop's turn makes none)
        Object[] pairs = answerPairs;
        if (pairs.length < 2 * vars.size()) {
            pairs = new Object[2 * vars.size()];
            answerPairs = pairs;
        }
        int n = 0;
        for (int k = 0; k < vars.size() + (more == null ? 0 : more.size()); k++) {
            Var v = k < vars.size() ? vars.get(k) : more.get(k - vars.size());
            Term b = w.binding(v);
            if (b == null) {
                continue;
            }
            Term value = b;
            if (w.boundSince(v, base)) {
                value = w.deref(b);
                if (n == pairs.length) {
                    pairs = Arrays.copyOf(pairs, 2 * n + 2);
                    answerPairs = pairs;
                }
                pairs[n++] = v;
                pairs[n++] = value;
            }
            if (value instanceof Var x) {
                if (more == null) {
                    more = new ArrayList<>();
                }
                seen = enqueue(x, vars, more, seen);
            } else if (!value.isGround()) {
                var found = new ArrayList<Var>();
                value.collectVars(found::add);
                if (more == null) {
                    more = new ArrayList<>();
                }
                for (Var x : found) {
                    seen = enqueue(x, vars, more, seen);
                }
            }
        }
        return n;
    }

    /**
     * Queues a variable not seen yet (neither the formula's nor queued). {@return the set of those
     * seen, made once the queue is long}
     */
    private static HashSet<Var> enqueue(Var x, List<Var> vars, ArrayList<Var> more, HashSet<Var> seen) {
        if (seen == null && vars.size() + more.size() > 16) {
            seen = new HashSet<>(vars);
            seen.addAll(more);
        }
        if (seen != null ? seen.add(x) : !vars.contains(x) && !more.contains(x)) {
            more.add(x);
        }
        return seen;
    }

    /** A plan's context: its first literal, a rule query, is looked up in and told to {@link FailedQueries}. */
    void rememberFailure() {
        remember = true;
    }

    private boolean run() {
        while (true) {
            if (fence != null && goals == fence.rest) {
                fence.proven = true; // the fenced query has a solution
            }
            if (goals == null) {
                return true;
            }
            Goals g = goals;
            goals = g.next;
            if (!step(g) && !backtrack()) {
                return false;
            }
        }
    }

    private boolean backtrack() {
        while (nChoices > 0) {
            Choice c = choices[nChoices - 1];
            w.undoTo(c.mark);
            if (c.resume(this)) {
                return true;
            }
        }
        return false;
    }

    private void push(Choice c) {
        if (nChoices == choices.length) {
            choices = Arrays.copyOf(choices, Math.max(8, 2 * nChoices));
        }
        choices[nChoices++] = c;
    }

    private void pop(Choice c) {
        if (nChoices > 0 && choices[nChoices - 1] == c) {
            choices[--nChoices] = null;
        }
    }

    /** One goal: {@return false when it fails here} (goals then holds what follows it) */
    private boolean step(Goals g) {
        int depth = g.depth;
        Term f = w.deref(g.goal());
        if (f instanceof AnnotatedVar av) {
            Term value = w.apply(av);
            if (!(value instanceof Literal)) {
                return branch(solver.annotated(av, w), w.size());
            }
            f = value;
        }
        if (f instanceof Literal l) {
            if (l.isAtom() && l.functor().equals("true")) {
                return true;
            }
            if (l.isAtom() && l.functor().equals("false")) {
                return false;
            }
            return l.isInternalAction() ? internalAction(l) : literal(l, depth);
        }
        if (f instanceof LogExpr e) {
            switch (e.op()) {
                case NOT: {
                    int mark = w.size();
                    boolean provable = new Proof(solver, e.left(), w, depth).next();
                    w.undoTo(mark);
                    return !provable;
                }
                case AND:
                    goals = g.conjunction(e);
                    return true;
                default:
                    push(new Alternative(w.size(), g.disjunct(e, true)));
                    goals = g.disjunct(e, false);
                    return true;
            }
        }
        if (f instanceof RelExpr r) {
            return solver.relational(r, w);
        }
        return false;
    }

    private boolean literal(Literal l, int depth) {
        Literal q = plain(l) ? l : (Literal) w.apply(l);
        List<BeliefBase.Entry> candidates = solver.candidates(q, w);
        if (remember) {
            remember = false;
            if (fenced(q, candidates)) {
                return false;
            }
        }
        switch (candidates.size()) {
            case 0:
                return false;
            case 1:
                return enter(q, candidates.get(0), goals, depth);
            default:
                var c = new Candidates(w.size(), goals, q, candidates, depth);
                push(c);
                return c.resume(this);
        }
    }

    /**
     * {@return whether the term has nothing to evaluate (no arithmetic)} Unifying such a query as
     * it is does what unifying it applied would, since unification follows bound variables
     * itself; applying it would copy the values bound so far, which grow with the proof in
     * recursions like {@code p(X) :- p(f(X))}.
     */
    private static boolean plain(Term t) {
        while (t instanceof ListTerm.Cons c) {
            if (!plain(c.head())) {
                return false;
            }
            t = c.tail();
        }
        if (t instanceof Literal l) {
            for (int i = 0, n = l.arity(); i < n; i++) {
                if (!plain(l.arg(i))) {
                    return false;
                }
            }
            List<Term> annots = l.annots();
            for (int i = 0, n = annots.size(); i < n; i++) {
                if (!plain(annots.get(i))) {
                    return false;
                }
            }
            return l.tail() == null || plain(l.tail());
        }
        return t instanceof Var || t instanceof NumberTerm || t instanceof StringTerm || t instanceof ListTerm.Empty;
    }

    /**
     * For the first literal of a context, when rules alone answer it: {@return true when it is known to
     * fail}; otherwise a {@link Fence} below its choices tells {@link FailedQueries} if it fails
     */
    private boolean fenced(Literal q, List<BeliefBase.Entry> candidates) {
        if (candidates.isEmpty()) {
            return false;
        }
        for (int i = 0, n = candidates.size(); i < n; i++) {
            if (candidates.get(i).rule() == null) {
                return false;
            }
        }
        FailedQueries.Key key = FailedQueries.key(q, w);
        if (key == null) {
            return false;
        }
        Agent agent = solver.agent();
        if (solver.failedQueries.fails(key, agent)) {
            return true;
        }
        fence = new Fence(w.size(), goals, key, solver.sideEffects(), agent.freshTaken(), agent.internalTaken());
        push(fence);
        return false;
    }

    /** Resolves the query with one belief or rule; the goals become {@code rest} after it. */
    private boolean enter(Literal q, BeliefBase.Entry e, Goals rest, int depth) {
        int mark = w.size();
        if (e.rule() != null) {
            Rule r = e.rule();
            Solver.Renaming renaming = solver.renaming(e);
            if (!renaming.headUnifies(q, r.head(), w)) {
                return false;
            }
            if (depth >= MAX_DEPTH) {
                throw new TooDeep();
            }
            // the body is renamed only once the head matched, goal by goal as the proof reaches each
            goals = new Goals(r.body(), rest, depth + 1, renaming);
            return true;
        }
        Literal belief = e.isGround() ? e.literal() : solver.renameApart(e.literal());
        if (!w.unifiesIgnoringAnnots(q, belief)) {
            return false;
        }
        goals = rest;
        if (q.annots().isEmpty() && q.tail() == null) {
            return true;
        }
        if (q.tail() != null) {
            // as Jason, b[x|T] matches a belief one way only (the first annotation x unifies with)
            if (!w.unifies(q, belief)) {
                w.undoTo(mark);
                return false;
            }
            return true;
        }
        var ways = new ArrayList<Object[]>(1);
        matchAnnots(q.annots(), 0, belief.annots(), new boolean[belief.annots().size()], mark, ways);
        w.undoTo(mark);
        return branch(ways, mark);
    }

    /** Every way of matching each query annotation with a distinct belief annotation, in order. */
    private void matchAnnots(List<Term> query, int i, List<Term> belief, boolean[] used, int mark, List<Object[]> out) {
        if (i == query.size()) {
            out.add(w.bindingsSince(mark));
            return;
        }
        for (int j = 0; j < belief.size(); j++) {
            int m = w.size();
            if (!used[j] && w.unifies(query.get(i), belief.get(j))) {
                used[j] = true;
                matchAnnots(query, i + 1, belief, used, mark, out);
                used[j] = false;
                w.undoTo(m);
            }
        }
    }

    /** Goes on with the first of several sets of bindings (made since {@code mark}), the others left as a choice. */
    private boolean branch(List<Object[]> ways, int mark) {
        if (ways.isEmpty()) {
            return false;
        }
        w.rebind(ways.get(0));
        if (ways.size() > 1) {
            push(new Ways(mark, goals, ways));
        }
        return true;
    }

    @SuppressWarnings("unchecked")
    private boolean internalAction(Literal l) {
        InternalAction ia = solver.internalAction(l);
        if (ia == null) {
            return false;
        }
        int mark = w.size();
        // the action gets its own unifier: an action answering with an iterator keeps it
        Unifier own = w.copy();
        Object result = solver.execute(ia, l, own);
        if (result instanceof Boolean b) {
            if (b) {
                w.rebind(own.bindingsSince(mark));
            }
            return b;
        }
        if (result instanceof Iterator<?> it) {
            var c = new Solutions(mark, goals, (Iterator<Unifier>) it);
            push(c);
            return c.resume(this);
        }
        return false;
    }

    // ---- choice points ---------------------------------------------------------------------------

    /**
     * Below the choices of a context's first query ({@link #fenced}): reached in backtracking once they are
     * all spent. If the proof never got past the query and did nothing beyond the belief base, the query
     * has no solution while the belief base stays as it is.
     */
    private static final class Fence extends Choice {
        private final FailedQueries.Key key;
        private final long sideEffects, fresh, internal;
        boolean proven;

        Fence(int mark, Goals rest, FailedQueries.Key key, long sideEffects, long fresh, long internal) {
            super(mark, rest);
            this.key = key;
            this.sideEffects = sideEffects;
            this.fresh = fresh;
            this.internal = internal;
        }

        @Override
        boolean resume(Proof p) {
            p.pop(this);
            Agent agent = p.solver.agent();
            if (!proven && p.solver.sideEffects() == sideEffects) {
                p.solver.failedQueries.failed(key, agent, agent.freshTaken() - fresh, agent.internalTaken() - internal);
            }
            return false;
        }
    }

    /** The right side of {@code |}. */
    private static final class Alternative extends Choice {
        Alternative(int mark, Goals rest) {
            super(mark, rest);
        }

        @Override
        boolean resume(Proof p) {
            p.pop(this);
            p.goals = rest;
            return true;
        }
    }

    /** The beliefs and rules left for a query. */
    private static final class Candidates extends Choice {
        private final Literal query;
        private final List<BeliefBase.Entry> entries;
        private final int depth;
        private int next;

        Candidates(int mark, Goals rest, Literal query, List<BeliefBase.Entry> entries, int depth) {
            super(mark, rest);
            this.query = query;
            this.entries = entries;
            this.depth = depth;
        }

        @Override
        boolean resume(Proof p) {
            while (next < entries.size()) {
                BeliefBase.Entry e = entries.get(next++);
                if (next == entries.size()) {
                    p.pop(this);
                }
                if (p.enter(query, e, rest, depth)) {
                    return true;
                }
                p.w.undoTo(mark);
            }
            p.pop(this);
            return false;
        }
    }

    /** Sets of bindings left to try (annotation matches, beliefs of an annotated variable). */
    private static final class Ways extends Choice {
        private final List<Object[]> ways;
        private int next = 1;

        Ways(int mark, Goals rest, List<Object[]> ways) {
            super(mark, rest);
            this.ways = ways;
        }

        @Override
        boolean resume(Proof p) {
            Object[] way = ways.get(next++);
            if (next == ways.size()) {
                p.pop(this);
            }
            p.w.rebind(way);
            p.goals = rest;
            return true;
        }
    }

    /** The solutions an internal action gives, each a unifier extending the one it was given. */
    private static final class Solutions extends Choice {
        private final Iterator<Unifier> it;

        Solutions(int mark, Goals rest, Iterator<Unifier> it) {
            super(mark, rest);
            this.it = it;
        }

        @Override
        boolean resume(Proof p) {
            if (it instanceof InternalAction.Solutions s) {
                // the bindings are back at the mark, which is what the action was given
                if (!s.nextInto(p.w)) {
                    p.pop(this);
                    return false;
                }
                p.goals = rest;
                return true;
            }
            if (!it.hasNext()) {
                p.pop(this);
                return false;
            }
            p.w.rebind(it.next().bindingsSince(mark));
            p.goals = rest;
            return true;
        }
    }
}
