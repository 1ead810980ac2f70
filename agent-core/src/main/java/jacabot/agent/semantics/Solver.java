package jacabot.agent.semantics;

import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TermMapper;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.NoSuchElementException;

/**
 * Logical consequence: the solutions (unifiers) of a formula against the belief base, rules,
 * relational expressions and internal actions, lazily and in Jason's order. Each solution is the
 * caller's unifier extended with the bindings of the formula's variables; a {@link Proof} does
 * the resolution.
 */
public final class Solver {
    private final Agent agent;
    /** What {@link FailedQueries} knows, and the count of what a proof did beyond the belief base ({@link #sideEffect}). */
    final FailedQueries failedQueries = new FailedQueries();
    private long sideEffects;

    Solver(Agent agent) {
        this.agent = agent;
    }

    Agent agent() {
        return agent;
    }

    /**
     * Counts something a proof did that the belief base alone does not decide (an internal action, a
     * random number, the time, a function defined by rules, a warning): a failed query that did one is
     * not remembered ({@link FailedQueries}).
     */
    void sideEffect() {
        sideEffects++;
    }

    long sideEffects() {
        return sideEffects;
    }

    /** {@return whether the formula has a solution; binds {@code u} to the first one} */
    public boolean believes(Term formula, Unifier u) {
        return believes(formula, u, false);
    }

    /** As {@link #believes}, for a plan's context: the rule query it begins with may be known to fail ({@link FailedQueries}). */
    boolean believesContext(Term formula, Unifier u) {
        return believes(formula, u, true);
    }

    private boolean believes(Term formula, Unifier u, boolean context) {
        if (formula instanceof RelExpr r) {
            // X = N * 2, N > 3: one solution at most, found without a proof
            return relational(r, u);
        }
        var proof = new Proof(this, formula, u, 0);
        if (context) {
            proof.rememberFailure();
        }
        if (proof.next()) {
            proof.keepAnswer();
            return true;
        }
        return false;
    }

    /**
     * {@return whether a plan context has no solution, seen without a proof} It is so when its
     * first conjunct is a comparison ({@code N mod 30 == 3}) that does not hold: a proof would fail
     * there before anything else. Of a goal's many plans, most fail so, and a proof is built for
     * each. Terms with function calls ({@code math.random}) are left to the proof, which evaluates
     * them once; so is a context of one relation, which {@link #believes} decides without a proof.
     */
    boolean failsAtFirstComparison(Term context, Unifier u) {
        if (context instanceof RelExpr) {
            return false;
        }
        Term first = context;
        while (first instanceof LogExpr e && e.op() == LogExpr.Op.AND) {
            first = e.left();
        }
        if (!(first instanceof RelExpr r) || r.op() == RelExpr.Op.UNIFY || r.op() == RelExpr.Op.UNIV
                || !withoutCalls(r.left(), u) || !withoutCalls(r.right(), u)) {
            return false;
        }
        return !relational(r, u); // a comparison binds nothing
    }

    /** {@return whether applying {@code u} to the term calls no function} (lists and the rarer terms: no, to be safe) */
    private static boolean withoutCalls(Term t, Unifier u) {
        if (t instanceof Var v) {
            Term d = u.deref(v);
            return d instanceof Var || withoutCalls(d, u);
        }
        if (t instanceof NumberTerm || t instanceof StringTerm) {
            return true;
        }
        if (t instanceof ArithExpr e) {
            // an operand that is no number is evaluated with a warning: left to the proof, once
            return numeric(e.left(), u) && (e.right() == null || numeric(e.right(), u));
        }
        if (t instanceof Literal l) {
            return l.ns() == null && l.tail() == null && allWithoutCalls(l.args(), u) && allWithoutCalls(l.annots(), u);
        }
        return false;
    }

    /** {@return whether an operand is a number, a free variable or an expression of those} */
    private static boolean numeric(Term t, Unifier u) {
        Term d = t instanceof Var ? u.deref(t) : t;
        return d instanceof NumberTerm || d instanceof Var || d instanceof ArithExpr && withoutCalls(d, u);
    }

    private static boolean allWithoutCalls(List<Term> terms, Unifier u) {
        for (int i = 0, n = terms.size(); i < n; i++) {
            if (!withoutCalls(terms.get(i), u)) {
                return false;
            }
        }
        return true;
    }

    /**
     * {@return the solutions of a formula, each an extension of {@code u} (never changed)} Taken
     * as an iterator, each solution is a unifier of its own; {@link Answers#next(Unifier)} gives
     * them into one unifier instead (a {@code for} loop's turns), without one made per solution.
     * One object is read one way only.
     */
    public Answers solve(Term formula, Unifier u) {
        return new Answers(new Proof(this, formula, u.copy(), 0));
    }

    /** The solutions of a proof: as unifiers of their own, or given one by one into a unifier. */
    public static final class Answers implements Iterator<Unifier> {
        private final Proof proof;
        private Unifier next;
        private boolean over;

        Answers(Proof proof) {
            this.proof = proof;
        }

        /**
         * {@return the same text for every object} A {@code for} loop carries its answers in its
         * step, which the mind's capture and the inspector print: an identity hash there would make
         * the step log of one seed differ from run to run.
         */
        @Override
        public String toString() {
            return "answers";
        }

        /** {@return whether there is another solution; {@code into} then holds it (else it is left as it was)} */
        public boolean next(Unifier into) {
            if (!proof.next()) {
                return false;
            }
            proof.solutionInto(into);
            return true;
        }

        @Override
        public boolean hasNext() {
            if (next == null && !over) {
                if (proof.next()) {
                    next = proof.solution();
                } else {
                    over = true;
                }
            }
            return next != null;
        }

        @Override
        public Unifier next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            Unifier u = next;
            next = null;
            return u;
        }
    }

    /** A formula and its distinct variables. */
    private record FormulaVars(Term formula, List<Var> vars) {
    }

    /** The last formula whose variables were asked (a loop asks for its condition's at every turn), in one field: other threads may ask too. */
    private FormulaVars lastVars = new FormulaVars(null, List.of());

    /** {@return the distinct variables of a formula, in order of first occurrence} */
    List<Var> varsOf(Term formula) {
        FormulaVars last = lastVars;
        if (last.formula() != formula) {
            var vars = new LinkedHashSet<Var>();
            formula.collectVars(vars::add);
            last = new FormulaVars(formula, List.copyOf(vars));
            lastVars = last;
        }
        return last.vars();
    }

    // ---- what a proof asks of the agent ----------------------------------------------------------

    /** {@return the beliefs and rules that may match a literal, in order} */
    List<BeliefBase.Entry> candidates(Literal q, Unifier u) {
        return agent.beliefBase().candidates(q, q.ns() instanceof Var nv ? u.deref(nv) : q.ns(),
                q.arity() == 0 ? null : u.deref(q.arg(0)));
    }

    /**
     * {@code _[source(a)]}: for every belief with these annotations, the bindings its unification
     * makes in {@code w} (which is left as it was).
     */
    List<Object[]> annotated(AnnotatedVar av, Unifier w) {
        sideEffect(); // not a side effect, but such queries are rare: their failures are not remembered (FailedQueries)
        var out = new ArrayList<Object[]>();
        int mark = w.size();
        for (BeliefBase.Entry e : agent.beliefBase().all()) {
            if (e.rule() == null && w.unifies(av, e.literal())) {
                out.add(w.bindingsSince(mark));
                w.undoTo(mark);
            }
        }
        return out;
    }

    /**
     * A rule's variables renamed apart from every other variable: fresh ones, made in order of
     * first occurrence (head, then body), as the rule is used.
     */
    static final class Renaming extends TermMapper {
        private final Var[] vars;
        /** The fresh variables, each made when first met: the numbers are taken at once, the objects only if used. */
        private final Var[] fresh;
        private final long firstSerial;

        Renaming(BeliefBase.Entry e, Agent agent) {
            vars = e.ruleVars();
            fresh = new Var[vars.length];
            firstSerial = agent.freshSerials(vars.length);
        }

        /** As the mapper's, without its intermediate lists (a proof renames at every step). */
        @Override
        public Term visitLiteral(Literal l) {
            int n = l.arity();
            if (n == 0 && l.annots().isEmpty() && l.ns() == null && l.tail() == null || l.isGround()) {
                return l;
            }
            List<Term> args;
            switch (n) {
                case 0:
                    args = List.of();
                    break;
                case 1:
                    args = List.of(map(l.arg(0)));
                    break;
                case 2:
                    args = List.of(map(l.arg(0)), map(l.arg(1)));
                    break;
                default:
                    Term[] a = new Term[n];
                    for (int i = 0; i < n; i++) {
                        a[i] = map(l.arg(i));
                    }
                    args = List.of(a);
                    break;
            }
            return new Literal(l.functor(), args, l.annots().isEmpty() ? l.annots() : mapAll(l.annots()), l.negated(),
                    false, l.ns() == null ? null : map(l.ns()), l.tail() == null ? null : map(l.tail()), l.src());
        }

        @Override
        public Term visitVar(Var v) {
            Var[] vs = vars;
            for (int i = 0; i < vs.length; i++) {
                if (vs[i] == v) { // the rule's occurrences are mostly the very objects ruleVars holds
                    return fresh(i);
                }
            }
            for (int i = 0; i < vs.length; i++) {
                if (vs[i].equals(v)) {
                    return fresh(i);
                }
            }
            return v;
        }

        /**
         * {@return whether the rule's head, renamed, unifies with query {@code q} as a proof enters the
         * rule: without annotations, then with them if the query has some} Nothing stays bound when
         * not. Where neither has a namespace and the query no annotations (nearly always), the
         * arguments are unified one by one, in the order the literals' unification takes, and the
         * renamed head is not built.
         */
        boolean headUnifies(Literal q, Literal head, Unifier w) {
            int mark = w.size();
            if (q.annots().isEmpty() && q.tail() == null && q.ns() == null && head.ns() == null) {
                if (!q.sameName(head)) {
                    return false;
                }
                for (int i = 0, n = q.arity(); i < n; i++) {
                    if (!w.unifies(q.arg(i), map(head.arg(i)))) {
                        w.undoTo(mark);
                        return false;
                    }
                }
                return true;
            }
            Literal h = (Literal) map(head);
            if (!w.unifiesIgnoringAnnots(q, h)) {
                return false;
            }
            if ((!q.annots().isEmpty() || q.tail() != null) && !w.unifies(q, h)) {
                w.undoTo(mark);
                return false;
            }
            return true;
        }

        private Var fresh(int i) {
            Var f = fresh[i];
            if (f == null) {
                f = new Var(vars[i].name(), firstSerial + i);
                fresh[i] = f;
            }
            return f;
        }
    }

    Renaming renaming(BeliefBase.Entry e) {
        return new Renaming(e, agent);
    }

    /**
     * A fact with variables, like in(X, [X|_]): its variables are its own. Jason queries such a fact
     * without renaming it, so the renaming takes no number of the counter of fresh variables.
     */
    Literal renameApart(Literal fact) {
        return (Literal) Renamer.renameApart(fact, agent::internalVar, new HashMap<>());
    }

    // ---- internal actions in formulas -----------------------------------------------------------

    /** {@return the internal action a formula names, or null (with a warning)} */
    InternalAction internalAction(Literal l) {
        sideEffect();
        InternalAction ia = agent.internalAction(l.functor());
        if (ia == null) {
            agent.warn("unknown internal action '" + l.functor() + "' in a formula");
        }
        return ia;
    }

    /** {@return what the action answers: a Boolean, an iterator of unifiers, or false after a warning} */
    Object execute(InternalAction ia, Literal l, Unifier u) {
        try {
            Term[] args = agent.prepareArguments(ia, l, u);
            return ia.execute(agent, u, args);
        } catch (IaException e) {
            agent.warn(e.getMessage());
            return Boolean.FALSE;
        }
    }

    // ---- relational expressions ---------------------------------------------------------------

    /** {@return whether the relation holds; a unification is made in {@code u} (nothing when it fails)} */
    boolean relational(RelExpr r, Unifier u) {
        Term x = u.apply(r.left());
        Term y = u.apply(r.right());
        switch (r.op()) {
            case UNIFY:
                return u.unifies(x, y);
            case UNIV:
                return univ(x, y, u);
            case EQ:
                return x.equals(y);
            case DIF:
                return !x.equals(y);
            default:
                int c = x.compareTo(y);
                boolean ok;
                switch (r.op()) {
                    case LT: ok = c < 0; break;
                    case LTE: ok = c <= 0; break;
                    case GT: ok = c > 0; break;
                    default: ok = c >= 0; break;
                }
                return ok;
        }
    }

    /** {@code T =.. L}: L is [namespace, functor, args, annots]; 2 and 3 elements also build. */
    private static boolean univ(Term x, Term y, Unifier c) {
        if (x instanceof Literal l) {
            // as Jason, a list of three leaves the namespace out
            boolean three = y instanceof ListTerm yl && yl.isProper() && yl.elements().size() == 3;
            Term functor = Literal.atom(l.functor());
            Term annots = l.tail() == null ? ListTerm.of(l.annots())
                    : l.annots().isEmpty() ? l.tail() : ListTerm.of(l.annots(), l.tail());
            Term decomposed = three ? ListTerm.of(functor, ListTerm.of(l.args()), annots)
                    : ListTerm.of(l.nsTerm(), functor, ListTerm.of(l.args()), annots);
            return c.unifies(decomposed, y);
        }
        if (x instanceof PlanTerm p) {
            // Jason's plan is the structure plan(Label, Trigger, Context, Body)
            Term label = p.label() == null ? new Var("_", Long.MIN_VALUE) : p.label();
            Term decomposed = ListTerm.of(label, new TriggerTerm(p.trigger()), p.contextOrTrue(), p.body());
            return c.unifies(decomposed, y);
        }
        if (x instanceof Var && y instanceof ListTerm list && list.elements().size() == 4
                && list.elements().get(1) instanceof TriggerTerm tt) {
            List<Term> parts = list.elements();
            Term context = parts.get(2).equals(Literal.TRUE) ? null : parts.get(2);
            var built = new PlanTerm(parts.get(0), tt.trigger(), context, parts.get(3), null);
            return c.unifies(x, built);
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
                return false;
            }
            String name = functor instanceof Literal fl ? fl.functor()
                    : functor instanceof StringTerm s ? s.value() : null;
            if (name == null || !(args instanceof ListTerm al) || !(annots instanceof ListTerm nl)) {
                return false;
            }
            Term ns = parts.size() == 4 ? parts.get(0) : null;
            // the annotations as the tail: the literal takes its elements, and its own tail if any
            Literal built = new Literal(name, al.elements(), List.of(), false, false, ns, nl);
            return c.unifies(x, built);
        }
        if (x instanceof NumberTerm || x instanceof StringTerm) {
            return c.unifies(ListTerm.of(x), y);
        }
        return false;
    }

}
