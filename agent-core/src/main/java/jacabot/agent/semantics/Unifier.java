package jacabot.agent.semantics;

import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;

/**
 * A substitution of variables by terms: the only mutable piece of the term machinery.
 * {@link #unifies} undoes its own bindings when it fails; {@link #copy()} makes an
 * independent copy for backtracking.
 */
public final class Unifier {
    private final Bindings bindings;
    /** Evaluates arithmetic functions; null means only plain arithmetic is evaluated. */
    private Evaluator evaluator;

    /** Evaluates {@link ArithFunction}s (they may need the agent, e.g. {@code .count}). */
    public interface Evaluator {
        /** {@return the function's value, or null when its arguments are not bound numbers} */
        Term evaluate(ArithFunction f, Unifier u);

        /** An operand of the expression, as {@code u} binds it, is no number: the expression is NaN. */
        default void notANumber(ArithExpr e, Unifier u) {
        }
    }

    public Unifier() {
        this.bindings = new Bindings();
    }

    private Unifier(Bindings bindings, Evaluator evaluator) {
        this.bindings = bindings;
        this.evaluator = evaluator;
    }

    public Unifier copy() {
        return new Unifier(bindings.copy(), evaluator);
    }

    public void setEvaluator(Evaluator evaluator) {
        this.evaluator = evaluator;
    }

    public Evaluator evaluator() {
        return evaluator;
    }

    /** Replaces this unifier's bindings with another's. */
    public void setFrom(Unifier other) {
        if (other != this) {
            bindings.setFrom(other.bindings);
        }
    }

    // ---- the trail, for the solver: bindings only append, so a mark is a size ---------------------

    int size() {
        return bindings.size();
    }

    /** Undoes every binding made since the unifier had {@code mark} bindings. */
    void undoTo(int mark) {
        bindings.truncate(mark);
    }

    /** {@return the bindings made since {@code mark}} */
    Object[] bindingsSince(int mark) {
        return bindings.suffix(mark);
    }

    /** Makes the bindings of a {@link #bindingsSince} again. */
    void rebind(Object[] pairs) {
        bindings.append(pairs, pairs.length);
    }

    /** Makes the bindings of the first {@code n} slots of {@code pairs} again. */
    void rebind(Object[] pairs, int n) {
        bindings.append(pairs, n);
    }

    /** {@return the variable's own binding (one step, not dereferenced), or null} */
    Term binding(Var v) {
        return bindings.get(v);
    }

    /** Replaces this unifier's bindings with the first {@code mark} of another's and then the first {@code n} slots of {@code pairs}. */
    void setFromPrefix(Unifier other, int mark, Object[] pairs, int n) {
        bindings.setFromPrefix(other.bindings, mark);
        bindings.append(pairs, n);
    }

    /** {@return a new unifier with this one's first {@code mark} bindings and then the first {@code n} slots of {@code pairs}} */
    Unifier prefixWith(int mark, Object[] pairs, int n) {
        var u = new Unifier(bindings.prefix(mark), evaluator);
        u.bindings.append(pairs, n);
        return u;
    }

    /** {@return whether the variable was bound once the unifier had {@code mark} bindings} */
    boolean boundSince(Var v, int mark) {
        return bindings.position(v) >= mark;
    }

    public boolean isEmpty() {
        return bindings.isEmpty();
    }

    /**
     * {@return the bindings now, for {@link #hasBindings} to tell later whether they changed} (the
     * mind probe prints a unifier again only when they did)
     */
    public Object[] bindingsNow() {
        return bindings.suffix(0);
    }

    /**
     * {@return whether the bindings are still those {@link #bindingsNow} gave: the same variables
     * bound to the same term objects, in the same order} Terms are immutable, so the unifier
     * prints the same (but for an object term, whose Java object may change).
     */
    public boolean hasBindings(Object[] then) {
        return bindings.samePairs(then);
    }

    public Map<Var, Term> bindings() {
        return Collections.unmodifiableMap(bindings.asMap());
    }

    /** {@return the term at the end of the variable's chain of bindings (itself when unbound)} */
    public Term deref(Term t) {
        while (t instanceof Var v) {
            Term b = bindings.get(v);
            if (b == null) {
                return v;
            }
            t = b;
        }
        return t;
    }

    /** {@return the value of a variable with every inner variable replaced, or null when unbound} */
    public Term get(Var v) {
        Term t = deref(v);
        return t instanceof Var ? null : apply(t);
    }

    /** Binds a variable directly (no check). */
    public void bind(Var v, Term value) {
        bindings.put(v, value);
    }

    public void unbind(Var v) {
        bindings.remove(v);
    }

    // ---- application (Substitution) -----------------------------------------------------------

    /** Replaces bound variables and evaluates arithmetic whose operands are all bound. */
    public Term apply(Term t) {
        return Substitution.apply(this, t);
    }

    List<Term> applyAll(List<Term> terms) {
        return Substitution.applyAll(this, terms);
    }

    // ---- unification -------------------------------------------------------------------------

    /**
     * Unifies two terms, binding variables of both. Annotations follow Jason: those of the first
     * term must be a subset of those of the second. Nothing is bound when it fails.
     */
    public boolean unifies(Term a, Term b) {
        int mark = bindings.size();
        if (unify(a, b)) {
            return true;
        }
        bindings.truncate(mark);
        return false;
    }

    /**
     * {@return a copy of this unifier extended by unifying a and b, or null when they do not
     * unify}; this unifier is left as it was
     */
    public Unifier unifiedCopy(Term a, Term b) {
        int mark = bindings.size();
        Unifier result = unify(a, b) ? copy() : null;
        bindings.truncate(mark);
        return result;
    }

    /**
     * As {@link #unifiedCopy} on the two literals without their annotations, without building
     * those literals (the belief base tries every candidate fact this way).
     */
    Unifier unifiedCopyIgnoringAnnots(Literal a, Literal b) {
        if (!a.sameName(b)) {
            return null;
        }
        int mark = bindings.size();
        Unifier result = unifyNs(a, b) && unifyArgs(a, b) ? copy() : null;
        bindings.truncate(mark);
        return result;
    }

    /** Unifies without annotation checks (annotations ignored on both sides). */
    public boolean unifiesIgnoringAnnots(Literal a, Literal b) {
        if (!a.sameName(b)) {
            return false;
        }
        int mark = bindings.size();
        if (unifyNs(a, b) && unifyArgs(a, b)) {
            return true;
        }
        bindings.truncate(mark);
        return false;
    }

    private boolean unifyArgs(Literal la, Literal lb) {
        for (int i = 0, n = la.arity(); i < n; i++) {
            if (!unify(la.arg(i), lb.arg(i))) {
                return false;
            }
        }
        return true;
    }

    private boolean unifyLiterals(Literal la, Literal lb) {
        if (!la.sameName(lb) || !unifyNs(la, lb) || !unifyArgs(la, lb)) {
            return false;
        }
        if (la.tail() == null && lb.tail() == null) {
            return la.annots().isEmpty() || subsetAnnots(la.annots(), lb.annots());
        }
        return unifyAnnotsWithTails(la, lb);
    }

    /** The annotations of two literals, one of them at least with a tail ({@code b[x|T]}). */
    private boolean unifyAnnotsWithTails(Literal la, Literal lb) {
        // a tail bound since the literal was built: its elements are annotations to match
        if (la.tail() != null && !(deref(la.tail()) instanceof Var)) {
            la = (Literal) apply(la);
        }
        if (lb.tail() != null && !(deref(lb.tail()) instanceof Var)) {
            lb = (Literal) apply(lb);
        }
        if (la.annots().isEmpty() && la.tail() == null) {
            return true;
        }
        // as Jason, d[|T] = d fails (and d = d[|T] succeeds, leaving T free)
        if (lb.annots().isEmpty() && lb.tail() == null) {
            return false;
        }
        return subsetAnnots(la.annots(), la.tail(), lb.annots(), lb.tail());
    }

    /** The namespaces of two literals (null, the default one, unifies with {@code default}). */
    private boolean unifyNs(Literal a, Literal b) {
        Term na = a.ns();
        Term nb = b.ns();
        return na == nb || unify(na == null ? Literal.DEFAULT_NS : na, nb == null ? Literal.DEFAULT_NS : nb);
    }

    /**
     * As Jason, a variable takes no literal of another namespace than the default one
     * ({@code X = ns::b} fails; {@code N::b = ns::b} binds N) and no local namespace's name.
     */
    private static boolean bindable(Term value) {
        return !(value instanceof Literal l) || l.ns() == null && !l.isLocalNsName();
    }

    /** Unifies, leaving the bindings made so far in place when it fails (callers cut them back). */
    private boolean unify(Term a, Term b) {
        a = deref(a);
        b = deref(b);
        // the usual cases first: two literals, two numbers (neither side a variable or arithmetic)
        if (a instanceof Literal la && b instanceof Literal lb) {
            return unifyLiterals(la, lb);
        }
        if (a instanceof NumberTerm na && b instanceof NumberTerm nb) {
            return na.equals(nb); // a NaN only with itself, as Jason's equals
        }
        if (a instanceof Var va) {
            if (b instanceof Var vb && va.equals(vb)) {
                return true;
            }
            if (!bindable(b) || b instanceof AnnotatedVar avb && avb.ns() != null && !unify(Literal.DEFAULT_NS, avb.ns())) {
                return false;
            }
            bindings.put(va, b);
            return true;
        }
        if (b instanceof Var vb) {
            if (!bindable(a) || a instanceof AnnotatedVar ava && ava.ns() != null && !unify(Literal.DEFAULT_NS, ava.ns())) {
                return false;
            }
            bindings.put(vb, a);
            return true;
        }
        if (a instanceof ArithExpr || a instanceof ArithFunction) {
            a = apply(a);
        }
        if (b instanceof ArithExpr || b instanceof ArithFunction) {
            b = apply(b);
        }
        if (a instanceof AnnotatedVar ava) {
            return unifyAnnotatedVar(ava, b, true);
        }
        if (b instanceof AnnotatedVar avb) {
            return unifyAnnotatedVar(avb, a, false);
        }
        if (a instanceof NumberTerm na) {
            return b instanceof NumberTerm nb && na.value() == nb.value();
        }
        if (a instanceof Literal la) {
            return b instanceof Literal lb && unifyLiterals(la, lb);
        }
        if (a instanceof ListTerm.Cons ca) {
            if (!(b instanceof ListTerm.Cons cb)) {
                return false;
            }
            return unify(ca.head(), cb.head()) && unify(ca.tail(), cb.tail());
        }
        if (a instanceof RelExpr ra) {
            return b instanceof RelExpr rb && ra.op() == rb.op()
                    && unify(ra.left(), rb.left()) && unify(ra.right(), rb.right());
        }
        if (a instanceof LogExpr ea) {
            return b instanceof LogExpr eb && ea.op() == eb.op() && unify(ea.left(), eb.left())
                    && (ea.right() == null ? eb.right() == null : eb.right() != null && unify(ea.right(), eb.right()));
        }
        if (a instanceof PlanTerm pa) {
            return b instanceof PlanTerm pb && unifyPlans(pa, pb);
        }
        if (a instanceof BodyTerm ba) {
            return b instanceof BodyTerm bb && unifyBodies(ba.steps(), bb.steps());
        }
        if (a instanceof TriggerTerm ta) {
            return b instanceof TriggerTerm tb && ta.trigger().op() == tb.trigger().op()
                    && ta.trigger().type() == tb.trigger().type()
                    && unify(ta.trigger().literal(), tb.trigger().literal());
        }
        if (a instanceof ArithExpr ea) {
            return b instanceof ArithExpr eb && ea.op() == eb.op() && unify(ea.left(), eb.left())
                    && (ea.right() == null ? eb.right() == null : eb.right() != null && unify(ea.right(), eb.right()));
        }
        return a.equals(b);
    }

    /**
     * {@code V[a1..an]} and a literal: the literal has (at least) those annotations and V is the
     * literal without its annotations. {@code left} tells on which side the annotated variable was (annotations of the
     * left term must be found in the right one).
     */
    private boolean unifyAnnotatedVar(AnnotatedVar av, Term other, boolean left) {
        Term d = deref(av.var());
        if (!(d instanceof Var v)) {
            Term value = apply(av);
            return left ? unify(value, other) : unify(other, value);
        }
        if (other instanceof AnnotatedVar o) {
            return (av.ns() == null && o.ns() == null || unify(nsOf(av), nsOf(o))) && unify(v, o.var());
        }
        if (!(other instanceof Literal l)) {
            // as Jason, ns::X = 10 binds X: only literals have namespaces and annotations
            if (av.ns() != null && av.annots().isEmpty() && av.tail() == null && !(other instanceof Var)) {
                bindings.put(v, other);
                return true;
            }
            return false;
        }
        if (av.ns() != null) {
            // ns::X and a literal: the namespaces unify, X takes the literal in the default namespace
            if (!unify(av.ns(), l.nsTerm())) {
                return false;
            }
            l = l.withNs(null);
        }
        if (av.tail() != null || l.tail() != null) {
            boolean ok = left ? subsetAnnots(av.annots(), av.tail(), l.annots(), l.tail())
                    : subsetAnnots(l.annots(), l.tail(), av.annots(), av.tail());
            if (!ok) {
                return false;
            }
        } else if (left && !subsetAnnots(av.annots(), l.annots())) {
            return false;
        } else if (!left && !subsetAnnots(l.annots(), av.annots())) {
            return false;
        }
        // as Jason, the variable stands for the literal; the annotations were matched apart
        if (!bindable(l)) {
            return false;
        }
        // (a variable with a namespace only, NS::W, keeps the annotations, as Jason's)
        bindings.put(v, av.annots().isEmpty() && av.tail() == null ? l : l.withoutAnnots());
        return true;
    }

    private static Term nsOf(AnnotatedVar av) {
        return av.ns() == null ? Literal.DEFAULT_NS : av.ns();
    }

    private boolean unifyPlans(PlanTerm a, PlanTerm b) {
        if (a.trigger().op() != b.trigger().op() || a.trigger().type() != b.trigger().type()) {
            return false;
        }
        if (a.label() != null && b.label() != null && !unify(a.label(), b.label())) {
            return false;
        }
        return unify(a.trigger().literal(), b.trigger().literal()) && unify(a.contextOrTrue(), b.contextOrTrue())
                && unify(a.body(), b.body());
    }

    /** Step by step; a variable as the last step of one body stands for the rest of the other. */
    private boolean unifyBodies(List<BodyStep> a, List<BodyStep> b) {
        for (int i = 0; ; i++) {
            if (i == a.size() || i == b.size()) {
                // { T; R } and { a }: R is the empty rest
                if (i == a.size() - 1 && isVarStep(a.get(i))) {
                    return unify(a.get(i).term(), BodyTerm.EMPTY);
                }
                if (i == b.size() - 1 && isVarStep(b.get(i))) {
                    return unify(BodyTerm.EMPTY, b.get(i).term());
                }
                return a.size() == b.size();
            }
            BodyStep sa = a.get(i);
            BodyStep sb = b.get(i);
            if (i == a.size() - 1 && isVarStep(sa) && b.size() >= a.size() && a.size() > 1) {
                return unify(sa.term(), new BodyTerm(b.subList(i, b.size())));
            }
            if (i == b.size() - 1 && isVarStep(sb) && a.size() >= b.size() && b.size() > 1) {
                return unify(new BodyTerm(a.subList(i, a.size())), sb.term());
            }
            if (isVarStep(sa) && !isAction(sb)) {
                if (!unify(sa.term(), BodyTerm.bare(sb))) {
                    return false;
                }
            } else if (isVarStep(sb) && !isAction(sa)) {
                if (!unify(BodyTerm.bare(sa), sb.term())) {
                    return false;
                }
            } else if (isVarStep(sa) || isVarStep(sb)) {
                if (!unify(sa.term(), sb.term())) {
                    return false;
                }
            } else if (sa.kind() != sb.kind() || !unify(sa.term(), sb.term())) {
                return false;
            }
        }
    }

    private static boolean isAction(BodyStep s) {
        return s.kind() == BodyStep.Kind.ACTION || s.kind() == BodyStep.Kind.INTERNAL_ACTION;
    }

    private boolean isVarStep(BodyStep s) {
        return s.kind() == BodyStep.Kind.ACTION && deref(s.term()) instanceof Var;
    }

    /** Each annotation of {@code sub} unifies with some annotation of {@code sup} (greedy, as Jason). */
    /**
     * Jason's subset test with tails: each annotation of {@code sub} unifies with one of
     * {@code sup}, or else goes to {@code sup}'s tail; {@code sub}'s tail takes what is left of
     * {@code sup}.
     */
    private boolean subsetAnnots(List<Term> sub, Term subTail, List<Term> sup, Term supTail) {
        var left = new ArrayList<Term>(sup);
        var extra = new ArrayList<Term>();
        for (Term x : sub) {
            boolean found = false;
            for (int j = 0; j < left.size(); j++) {
                int mark = bindings.size();
                if (unify(x, left.get(j))) {
                    left.remove(j);
                    found = true;
                    break;
                }
                bindings.truncate(mark);
            }
            if (!found) {
                if (supTail == null) {
                    return false;
                }
                extra.add(x);
            }
        }
        if (!extra.isEmpty() && !unify(supTail, ListTerm.of(extra))) {
            return false;
        }
        // as Jason, d[a|T] = d[a,b|U] gives T = [b|U], but d[a|T] = d[a|U] gives T = []
        return subTail == null || unify(subTail, supTail == null || left.isEmpty() ? ListTerm.of(left) : ListTerm.of(left, supTail));
    }

    /** {@return whether each annotation of {@code sub} unifies with one of {@code sup}} Nothing is bound when not. */
    boolean unifiesAnnots(List<Term> sub, List<Term> sup) {
        int mark = bindings.size();
        if (subsetAnnots(sub, sup)) {
            return true;
        }
        bindings.truncate(mark);
        return false;
    }

    private boolean subsetAnnots(List<Term> sub, List<Term> sup) {
        for (int i = 0, n = sub.size(); i < n; i++) {
            Term x = sub.get(i);
            boolean found = false;
            for (int j = 0, m = sup.size(); j < m; j++) {
                int mark = bindings.size();
                if (unify(x, sup.get(j))) {
                    found = true;
                    break;
                }
                bindings.truncate(mark);
            }
            if (!found) {
                return false;
            }
        }
        return true;
    }

    @Override
    public String toString() {
        // as Jason prints its unifier's map: {X=1, Y=a}
        var sb = new StringBuilder("{");
        bindings.asMap().forEach((k, v) -> {
            if (sb.length() > 1) {
                sb.append(", ");
            }
            sb.append(k).append('=').append(v);
        });
        return sb.append('}').toString();
    }
}
