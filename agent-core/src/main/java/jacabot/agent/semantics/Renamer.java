package jacabot.agent.semantics;

import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/** Structural renaming of variables (no evaluation), e.g. to rename a rule or an event apart. */
final class Renamer {
    private Renamer() {
    }

    static Term rename(Term t, Map<Var, Var> map) {
        return map(t, v -> map.getOrDefault(v, v));
    }

    /** Replaces every variable with the result of {@code f}. */
    static Term map(Term t, Function<Var, Term> f) {
        if (t instanceof Var v) {
            return f.apply(v);
        }
        if (t instanceof Literal l) {
            if (l.isGround()) {
                return l;
            }
            return new Literal(l.functor(), mapAll(l.args(), f), mapAll(l.annots(), f), l.negated());
        }
        if (t instanceof ListTerm.Cons c) {
            return new ListTerm.Cons(map(c.head(), f), map(c.tail(), f));
        }
        if (t instanceof ArithExpr e) {
            return new ArithExpr(e.op(), map(e.left(), f), e.right() == null ? null : map(e.right(), f));
        }
        if (t instanceof ArithFunction a) {
            return new ArithFunction(a.name(), mapAll(a.args(), f));
        }
        if (t instanceof RelExpr r) {
            return new RelExpr(r.op(), map(r.left(), f), map(r.right(), f));
        }
        if (t instanceof LogExpr e) {
            return new LogExpr(e.op(), map(e.left(), f), e.right() == null ? null : map(e.right(), f));
        }
        if (t instanceof TriggerTerm tt) {
            return new TriggerTerm(tt.trigger().withLiteral(map(tt.trigger().literal(), f)));
        }
        if (t instanceof BodyTerm b) {
            var steps = new ArrayList<BodyStep>();
            for (BodyStep s : b.steps()) {
                steps.add(s.withTerm(map(s.term(), f)));
            }
            return new BodyTerm(steps);
        }
        return t;
    }

    private static List<Term> mapAll(List<Term> terms, Function<Var, Term> f) {
        if (terms.isEmpty()) {
            return terms;
        }
        var out = new ArrayList<Term>(terms.size());
        for (Term t : terms) {
            out.add(map(t, f));
        }
        return out;
    }
}
