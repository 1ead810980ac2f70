package jacabot.agent.semantics;

import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;

/**
 * A unifier applied to a term ({@link Unifier#apply}): bound variables replaced, arithmetic
 * whose operands are bound evaluated. A term with nothing to replace comes back as it is.
 */
final class Substitution {
    private Substitution() {
    }

    /** Replaces bound variables and evaluates arithmetic whose operands are all bound. */
    static Term apply(Unifier u, Term t) {
        if (t instanceof Var v) {
            // as Jason's capply: a variable bound only to other free variables stays itself, so the
            // applied term no longer shares them (X = Y; +p(X, Y) adds p(X, Y) with two variables)
            Term d = u.deref(v);
            return d instanceof Var ? v : d instanceof NumberTerm ? d : apply(u, d);
        }
        if (t instanceof NumberTerm || t instanceof StringTerm) {
            return t; // before the long list of compound kinds below
        }
        if (t instanceof Literal l) {
            if (!needsApply(u, l)) {
                return l;
            }
            // a tail bound to a list brings its elements into the annotations (the constructor's work)
            return new Literal(l.functor(), applyAll(u, l.args()), applyAll(u, l.annots()), l.negated(), false,
                    l.ns() == null ? null : apply(u, l.ns()), l.tail() == null ? null : apply(u, l.tail()), l.src());
        }
        if (t instanceof ListTerm.Cons) {
            if (!needsApply(u, t)) {
                return t;
            }
            var items = new ArrayList<Term>();
            Term x = t;
            while (x instanceof ListTerm.Cons c) {
                items.add(apply(u, c.head()));
                x = c.tail();
                if (x instanceof Var) {
                    x = u.deref(x);
                }
            }
            return ListTerm.of(items, x instanceof ListTerm ? x : apply(u, x));
        }
        if (t instanceof ArithExpr e) {
            return arithmetic(u, e);
        }
        if (t instanceof ArithFunction f) {
            if (u.evaluator() != null) {
                Term value = u.evaluator().evaluate(new ArithFunction(f.name(), applyAll(u, f.args())), u);
                if (value != null) {
                    return value;
                }
            }
            // as Jason's copy of a function it cannot evaluate yet: as written (math.max(X,Z))
            return f;
        }
        if (t instanceof RelExpr r) {
            return new RelExpr(r.op(), apply(u, r.left()), apply(u, r.right()));
        }
        if (t instanceof LogExpr e) {
            return new LogExpr(e.op(), apply(u, e.left()), e.right() == null ? null : apply(u, e.right()));
        }
        if (t instanceof TriggerTerm tt) {
            return new TriggerTerm(tt.trigger().withLiteral(apply(u, tt.trigger().literal())), tt.bare());
        }
        if (t instanceof BodyTerm b) {
            var steps = new ArrayList<BodyStep>(b.steps().size());
            for (BodyStep s : b.steps()) {
                steps.add(s.withTerm(apply(u, s.term())));
            }
            return new BodyTerm(steps, b.braced());
        }
        if (t instanceof PlanTerm p) {
            return new PlanTerm(p.label() == null ? null : apply(u, p.label()),
                    p.trigger().withLiteral(apply(u, p.trigger().literal())),
                    p.context() == null ? null : apply(u, p.context()), apply(u, p.body()), p.source(), p.bare());
        }
        if (t instanceof AnnotatedVar av) {
            Term d = u.deref(av.var());
            List<Term> annots = applyAll(u, av.annots());
            Term ns = av.ns() == null ? null : apply(u, av.ns());
            if (d instanceof Var) {
                return new AnnotatedVar(av.var(), annots, av.tail() == null ? null : apply(u, av.tail()), ns);
            }
            return av.wrap(apply(u, d), annots, ns);
        }
        return t;
    }

    /**
     * Jason's evaluation of an expression, operands left to right: one that cannot be solved yet (a
     * free variable, an expression or function over one) leaves the expression as written, its
     * variables unreplaced, as Jason's copy of it; one bound to what is no number (an atom, a string,
     * a list) makes it NaN, with Jason's warning.
     */
    private static Term arithmetic(Unifier u, ArithExpr e) {
        Term l = apply(u, e.left());
        if (!(l instanceof NumberTerm nl)) {
            return unsolved(l) ? e : notANumber(u, e);
        }
        if (e.isUnary()) {
            return e.op() == ArithExpr.Op.MINUS ? new NumberTerm(-nl.value()) : nl;
        }
        Term r = apply(u, e.right());
        if (!(r instanceof NumberTerm nr)) {
            return unsolved(r) ? e : notANumber(u, e);
        }
        return new NumberTerm(e.op().apply(nl.value(), nr.value()));
    }

    /** {@return whether an operand is a number still to come: Jason's numeric terms with no value yet} */
    private static boolean unsolved(Term operand) {
        return operand instanceof Var || operand instanceof AnnotatedVar || operand instanceof ArithExpr
                || operand instanceof ArithFunction;
    }

    private static Term notANumber(Unifier u, ArithExpr e) {
        if (u.evaluator() != null) {
            u.evaluator().notANumber(e, u);
        }
        return new NumberTerm(Double.NaN);
    }

    /**
     * {@return whether applying this unifier changes the term: it has a bound variable or
     * arithmetic} A term whose variables are all free comes back as it is, not copied.
     */
    private static boolean needsApply(Unifier u, Term t) {
        if (t instanceof Var v) {
            return u.binding(v) != null;
        }
        if (t instanceof NumberTerm || t instanceof StringTerm) {
            return false;
        }
        if (t instanceof Literal l) {
            if (l.ns() instanceof Var nv && u.binding(nv) != null || l.tail() != null && needsApply(u, l.tail())) {
                return true;
            }
            List<Term> args = l.args();
            for (int i = 0, n = args.size(); i < n; i++) {
                if (needsApply(u, args.get(i))) {
                    return true;
                }
            }
            List<Term> annots = l.annots();
            for (int i = 0, n = annots.size(); i < n; i++) {
                if (needsApply(u, annots.get(i))) {
                    return true;
                }
            }
            return false;
        }
        if (t instanceof ListTerm) {
            Term x = t;
            while (x instanceof ListTerm.Cons c) {
                if (needsApply(u, c.head())) {
                    return true;
                }
                x = c.tail();
            }
            return x instanceof Var v ? u.binding(v) != null : !(x instanceof ListTerm.Empty);
        }
        return !(t instanceof ObjectTerm);
    }

    static List<Term> applyAll(Unifier u, List<Term> terms) {
        // one and two terms (most literals) without the array List.of(array) would copy
        switch (terms.size()) {
            case 0:
                return terms;
            case 1:
                return List.of(apply(u, terms.get(0)));
            case 2:
                return List.of(apply(u, terms.get(0)), apply(u, terms.get(1)));
            default:
                break;
        }
        Term[] out = new Term[terms.size()];
        for (int i = 0; i < out.length; i++) {
            out[i] = apply(u, terms.get(i));
        }
        return List.of(out);
    }
}
