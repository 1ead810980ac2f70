package jacabot.agent.semantics;

import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;

/**
 * Logical consequence: the solutions (unifiers) of a formula against the belief base, rules,
 * relational expressions and internal actions, lazily and in Jason's order.
 */
public final class Solver {
    private final Agent agent;

    Solver(Agent agent) {
        this.agent = agent;
    }

    /** {@return whether the formula has a solution; binds {@code u} to the first one} */
    public boolean believes(Term formula, Unifier u) {
        Iterator<Unifier> it = solve(formula, u);
        if (it.hasNext()) {
            u.setFrom(it.next());
            return true;
        }
        return false;
    }

    /** {@return the solutions of a formula, each an extension of {@code u} (never changed)} */
    public Iterator<Unifier> solve(Term formula, Unifier u) {
        Term f = u.deref(formula);
        if (f instanceof Var) {
            return Collections.emptyIterator();
        }
        if (f instanceof jacabot.agent.syntax.AnnotatedVar av) {
            Term value = u.apply(av);
            if (!(value instanceof Literal)) {
                // _[source(a)]: every belief with these annotations
                var out = new ArrayList<Unifier>();
                for (BeliefBase.Entry e : agent.beliefBase().all()) {
                    Unifier c = u.copy();
                    if (e.rule() == null && c.unifies(av, e.literal())) {
                        out.add(c);
                    }
                }
                return out.iterator();
            }
            f = value;
        }
        if (f instanceof Literal l) {
            // l.equals(TRUE) and l.equals(FALSE), without comparing every query's arguments
            if (l.isAtom() && l.functor().equals("true")) {
                return single(u.copy());
            }
            if (l.isAtom() && l.functor().equals("false")) {
                return Collections.emptyIterator();
            }
            if (l.isInternalAction()) {
                return internalAction(l, u);
            }
            return literal(l, u);
        }
        if (f instanceof LogExpr e) {
            switch (e.op()) {
                case NOT:
                    return solve(e.left(), u).hasNext() ? Collections.emptyIterator() : single(u.copy());
                case AND:
                    return new Conjunction(solve(e.left(), u), e.right());
                default:
                    return new Concat(solve(e.left(), u), () -> solve(e.right(), u));
            }
        }
        if (f instanceof RelExpr r) {
            return relational(r, u);
        }
        return Collections.emptyIterator();
    }

    // ---- literals against the belief base ------------------------------------------------------

    private Iterator<Unifier> literal(Literal query, Unifier u) {
        Literal q = (Literal) u.apply(query);
        List<BeliefBase.Entry> candidates = agent.beliefBase().candidates(q);
        if (candidates.isEmpty()) {
            return Collections.emptyIterator();
        }
        return new Candidates(candidates, q, u);
    }

    private Iterator<Unifier> match(Literal q, BeliefBase.Entry e, Unifier u) {
        if (e.rule() != null) {
            Rule r = rename(e.rule());
            Unifier ru = u.unifiedCopyIgnoringAnnots(q, r.head());
            if (ru == null) {
                return Collections.emptyIterator();
            }
            if (!q.annots().isEmpty() && !ru.unifies(q, r.head())) {
                return Collections.emptyIterator();
            }
            return solve(r.body(), ru);
        }
        Literal belief = e.literal();
        if (!e.isGround()) {
            // a fact with variables, like in(X, [X|_]): its variables are its own
            belief = (Literal) Renamer.renameApart(belief, agent);
        }
        // most candidates fail: unify first, copy only on success
        Unifier bu = u.unifiedCopyIgnoringAnnots(q, belief);
        if (bu == null) {
            return Collections.emptyIterator();
        }
        if (q.annots().isEmpty()) {
            return single(bu);
        }
        return annotationMatches(q.annots(), belief.annots(), bu);
    }

    /** Every way of matching each query annotation with a distinct belief annotation, in order. */
    private static Iterator<Unifier> annotationMatches(List<Term> query, List<Term> belief, Unifier u) {
        var out = new ArrayList<Unifier>();
        matchAnnots(query, 0, belief, new boolean[belief.size()], u, out);
        return out.iterator();
    }

    private static void matchAnnots(List<Term> query, int i, List<Term> belief, boolean[] used, Unifier u,
            List<Unifier> out) {
        if (i == query.size()) {
            out.add(u);
            return;
        }
        for (int j = 0; j < belief.size(); j++) {
            if (!used[j]) {
                Unifier next = u.copy();
                if (next.unifies(query.get(i), belief.get(j))) {
                    used[j] = true;
                    matchAnnots(query, i + 1, belief, used, next, out);
                    used[j] = false;
                }
            }
        }
    }

    /** Renames a rule's variables apart from every other variable. */
    private Rule rename(Rule r) {
        var map = new HashMap<Var, Var>();
        Term head = Renamer.renameApart(r.head(), agent::freshVar, map);
        Term body = Renamer.renameApart(r.body(), agent::freshVar, map);
        if (map.isEmpty()) {
            return r;
        }
        return new Rule((Literal) head, body);
    }

    // ---- internal actions in formulas -----------------------------------------------------------

    @SuppressWarnings("unchecked")
    private Iterator<Unifier> internalAction(Literal l, Unifier u) {
        InternalAction ia = agent.internalAction(l.functor());
        if (ia == null) {
            agent.warn("unknown internal action '" + l.functor() + "' in a formula");
            return Collections.emptyIterator();
        }
        Unifier copy = u.copy();
        try {
            Term[] args = agent.prepareArguments(ia, l, copy);
            Object result = ia.execute(agent, copy, args);
            if (result instanceof Boolean b) {
                return b ? single(copy) : Collections.emptyIterator();
            }
            if (result instanceof Iterator<?> it) {
                return (Iterator<Unifier>) it;
            }
            return Collections.emptyIterator();
        } catch (IaException e) {
            agent.warn(e.getMessage());
            return Collections.emptyIterator();
        }
    }

    // ---- relational expressions ---------------------------------------------------------------

    private Iterator<Unifier> relational(RelExpr r, Unifier u) {
        Term x = u.apply(r.left());
        Term y = u.apply(r.right());
        switch (r.op()) {
            case UNIFY: {
                Unifier c = u.copy();
                return c.unifies(x, y) ? single(c) : Collections.emptyIterator();
            }
            case UNIV:
                return univ(x, y, u);
            case EQ:
                return x.equals(y) ? single(u.copy()) : Collections.emptyIterator();
            case DIF:
                return !x.equals(y) ? single(u.copy()) : Collections.emptyIterator();
            default:
                int c = x.compareTo(y);
                boolean ok;
                switch (r.op()) {
                    case LT: ok = c < 0; break;
                    case LTE: ok = c <= 0; break;
                    case GT: ok = c > 0; break;
                    default: ok = c >= 0; break;
                }
                return ok ? single(u.copy()) : Collections.emptyIterator();
        }
    }

    /** {@code T =.. L}: L is [namespace, functor, args, annots]; 2 and 3 elements also build. */
    private Iterator<Unifier> univ(Term x, Term y, Unifier u) {
        Unifier c = u.copy();
        if (x instanceof Literal l) {
            Term decomposed = ListTerm.of(Literal.atom("default"), Literal.atom(l.functor()),
                    ListTerm.of(l.args()), ListTerm.of(l.annots()));
            return c.unifies(decomposed, y) ? single(c) : Collections.emptyIterator();
        }
        if (x instanceof PlanTerm p) {
            // Jason's plan is the structure plan(Label, Trigger, Context, Body)
            Term label = p.label() == null ? new Var("_", Long.MIN_VALUE) : p.label();
            Term decomposed = ListTerm.of(label, new TriggerTerm(p.trigger()), p.contextOrTrue(), p.body());
            return c.unifies(decomposed, y) ? single(c) : Collections.emptyIterator();
        }
        if (x instanceof Var && y instanceof ListTerm list && list.elements().size() == 4
                && list.elements().get(1) instanceof TriggerTerm tt) {
            List<Term> parts = list.elements();
            Term context = parts.get(2).equals(Literal.TRUE) ? null : parts.get(2);
            var built = new PlanTerm(parts.get(0), tt.trigger(), context, parts.get(3), null);
            return c.unifies(x, built) ? single(c) : Collections.emptyIterator();
        }
        if (x instanceof Var && y instanceof ListTerm list) {
            List<Term> parts = list.elements();
            Term functor;
            Term args;
            Term annots = ListTerm.EMPTY;
            if (parts.size() == 2) {
                functor = parts.get(0);
                args = parts.get(1);
            } else if (parts.size() == 3) {
                functor = parts.get(0);
                args = parts.get(1);
                annots = parts.get(2);
            } else if (parts.size() == 4) {
                functor = parts.get(1);
                args = parts.get(2);
                annots = parts.get(3);
            } else {
                return Collections.emptyIterator();
            }
            String name = functor instanceof Literal fl ? fl.functor()
                    : functor instanceof StringTerm s ? s.value() : null;
            if (name == null || !(args instanceof ListTerm al) || !(annots instanceof ListTerm nl)) {
                return Collections.emptyIterator();
            }
            Literal built = new Literal(name, al.elements(), nl.elements(), false);
            return c.unifies(x, built) ? single(c) : Collections.emptyIterator();
        }
        if (x instanceof NumberTerm || x instanceof StringTerm) {
            return c.unifies(ListTerm.of(x), y) ? single(c) : Collections.emptyIterator();
        }
        return Collections.emptyIterator();
    }

    // ---- lazy iterator helpers -----------------------------------------------------------------

    static Iterator<Unifier> single(Unifier u) {
        return new Single(u);
    }

    /** One solution (a single object, where a singleton list and its iterator are two). */
    private static final class Single implements Iterator<Unifier> {
        private Unifier next;

        Single(Unifier u) {
            this.next = u;
        }

        @Override
        public boolean hasNext() {
            return next != null;
        }

        @Override
        public Unifier next() {
            if (next == null) {
                throw new NoSuchElementException();
            }
            Unifier u = next;
            next = null;
            return u;
        }
    }

    /** Lazily, the solutions of one source after another (the shape of {@code &} and of candidates). */
    private abstract static class Chain implements Iterator<Unifier> {
        private Iterator<Unifier> current = Collections.emptyIterator();

        /** {@return the solutions of the next source, or null when there is none left} */
        abstract Iterator<Unifier> nextSource();

        @Override
        public final boolean hasNext() {
            while (!current.hasNext()) {
                Iterator<Unifier> source = nextSource();
                if (source == null) {
                    return false;
                }
                current = source;
            }
            return true;
        }

        @Override
        public final Unifier next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            return current.next();
        }
    }

    /** The solutions of one conjunct after another (one object per {@code &}). */
    private final class Conjunction extends Chain {
        private final Iterator<Unifier> left;
        private final Term right;

        Conjunction(Iterator<Unifier> left, Term right) {
            this.left = left;
            this.right = right;
        }

        @Override
        Iterator<Unifier> nextSource() {
            return left.hasNext() ? solve(right, left.next()) : null;
        }
    }

    /** The solutions of a query against each candidate belief or rule in turn. */
    private final class Candidates extends Chain {
        private final List<BeliefBase.Entry> entries;
        private final Literal query;
        private final Unifier u;
        private int next;

        Candidates(List<BeliefBase.Entry> entries, Literal query, Unifier u) {
            this.entries = entries;
            this.query = query;
            this.u = u;
        }

        @Override
        Iterator<Unifier> nextSource() {
            return next == entries.size() ? null : match(query, entries.get(next++), u);
        }
    }

    /** The first iterator's solutions, then the second's (computed only when reached). */
    private static final class Concat implements Iterator<Unifier> {
        private final Iterator<Unifier> first;
        private final java.util.function.Supplier<Iterator<Unifier>> second;
        private Iterator<Unifier> rest;

        Concat(Iterator<Unifier> first, java.util.function.Supplier<Iterator<Unifier>> second) {
            this.first = first;
            this.second = second;
        }

        @Override
        public boolean hasNext() {
            if (first.hasNext()) {
                return true;
            }
            if (rest == null) {
                rest = second.get();
            }
            return rest.hasNext();
        }

        @Override
        public Unifier next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            return first.hasNext() ? first.next() : rest.next();
        }
    }
}
