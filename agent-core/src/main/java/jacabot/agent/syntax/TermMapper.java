package jacabot.agent.syntax;

import java.util.ArrayList;
import java.util.List;

/**
 * Rebuilds a term with every variable replaced by {@link #visitVar}; the one structural walk that
 * renaming and substitution share. Ground parts are returned as they are.
 */
public abstract class TermMapper implements TermVisitor<Term> {

    public final Term map(Term t) {
        return t.accept(this);
    }

    public final List<Term> mapAll(List<Term> terms) {
        if (terms.isEmpty()) {
            return terms;
        }
        var out = new ArrayList<Term>(terms.size());
        for (Term t : terms) {
            out.add(map(t));
        }
        return out;
    }

    @Override
    public Term visitLiteral(Literal l) {
        if (l.isGround()) {
            return l;
        }
        return new Literal(l.functor(), mapAll(l.args()), mapAll(l.annots()), l.negated(), false,
                l.ns() == null ? null : map(l.ns()), l.tail() == null ? null : map(l.tail()), l.src());
    }

    @Override
    public Term visitNumber(NumberTerm t) {
        return t;
    }

    @Override
    public Term visitString(StringTerm t) {
        return t;
    }

    @Override
    public Term visitEmptyList(ListTerm.Empty t) {
        return t;
    }

    @Override
    public Term visitCons(ListTerm.Cons c) {
        return new ListTerm.Cons(map(c.head()), map(c.tail()));
    }

    @Override
    public Term visitArith(ArithExpr e) {
        return e.with(map(e.left()), e.right() == null ? null : map(e.right()));
    }

    @Override
    public Term visitRel(RelExpr r) {
        return new RelExpr(r.op(), map(r.left()), map(r.right()));
    }

    @Override
    public Term visitLog(LogExpr e) {
        return new LogExpr(e.op(), map(e.left()), e.right() == null ? null : map(e.right()));
    }

    @Override
    public Term visitFunction(ArithFunction a) {
        return new ArithFunction(a.name(), mapAll(a.args()));
    }

    @Override
    public Term visitTrigger(TriggerTerm tt) {
        return new TriggerTerm(tt.trigger().withLiteral(map(tt.trigger().literal())), tt.bare());
    }

    @Override
    public Term visitBody(BodyTerm b) {
        var steps = new ArrayList<BodyStep>();
        for (BodyStep s : b.steps()) {
            steps.add(s.withTerm(map(s.term())));
        }
        return new BodyTerm(steps, b.braced());
    }

    @Override
    public Term visitAnnotatedVar(AnnotatedVar t) {
        Term v = visitVar(t.var());
        List<Term> annots = mapAll(t.annots());
        Term ns = t.ns() == null ? null : map(t.ns());
        if (v instanceof Var nv) {
            return new AnnotatedVar(nv, annots, t.tail() == null ? null : map(t.tail()), ns);
        }
        return t.wrap(v, annots, ns);
    }

    @Override
    public Term visitPlan(PlanTerm p) {
        return new PlanTerm(p.label() == null ? null : map(p.label()), p.trigger().withLiteral(map(p.trigger().literal())),
                p.context() == null ? null : map(p.context()), map(p.body()), p.source(), p.bare());
    }

    @Override
    public Term visitObject(ObjectTerm t) {
        return t;
    }
}
