package jacabot.app.inspector;

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
import jacabot.agent.syntax.TermVisitor;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.lang.reflect.RecordComponent;
import java.util.List;

/**
 * Whether a term's text cannot change: terms are immutable, but an object term prints its Java
 * object, which may (a queue, a map, a loop's saved unifier). An object term holding a value, a
 * record made of strings, numbers, booleans, enums and such records (an artifact's id), is
 * stable. The mind probe keeps the text of a term only when it is stable, and prints the others
 * again at every capture.
 */
final class StableText implements TermVisitor<Boolean> {
    private static final StableText VISITOR = new StableText();
    /** Whether a class's objects are values (see {@link #isValue(Class, int)}), decided once per class. */
    private static final ClassValue<Boolean> VALUES = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            return isValue(type, 0);
        }
    };

    private StableText() {
    }

    /** {@return whether the term (null: none) prints the same for as long as it is the same object} */
    static boolean of(Term t) {
        return t == null || t.accept(VISITOR);
    }

    /** {@return whether every term of the list is stable} */
    static boolean all(List<Term> terms) {
        for (int i = 0, n = terms.size(); i < n; i++) {
            if (!of(terms.get(i))) {
                return false;
            }
        }
        return true;
    }

    static boolean of(BodyStep s) {
        return of(s.term());
    }

    @Override
    public Boolean visitLiteral(Literal t) {
        return all(t.args()) && all(t.annots()) && of(t.ns()) && of(t.tail());
    }

    @Override
    public Boolean visitNumber(NumberTerm t) {
        return true;
    }

    @Override
    public Boolean visitString(StringTerm t) {
        return true;
    }

    @Override
    public Boolean visitVar(Var t) {
        return true;
    }

    @Override
    public Boolean visitAnnotatedVar(AnnotatedVar t) {
        return all(t.annots()) && of(t.tail()) && of(t.ns());
    }

    @Override
    public Boolean visitEmptyList(ListTerm.Empty t) {
        return true;
    }

    @Override
    public Boolean visitCons(ListTerm.Cons t) {
        // a long list is a chain of cells: walk it, not recurse down it
        Term rest = t;
        while (rest instanceof ListTerm.Cons c) {
            if (!of(c.head())) {
                return false;
            }
            rest = c.tail();
        }
        return of(rest);
    }

    @Override
    public Boolean visitArith(ArithExpr t) {
        return of(t.left()) && of(t.right());
    }

    @Override
    public Boolean visitRel(RelExpr t) {
        return of(t.left()) && of(t.right());
    }

    @Override
    public Boolean visitLog(LogExpr t) {
        return of(t.left()) && of(t.right());
    }

    @Override
    public Boolean visitFunction(ArithFunction t) {
        return all(t.args());
    }

    @Override
    public Boolean visitTrigger(TriggerTerm t) {
        return of(t.trigger().literal());
    }

    @Override
    public Boolean visitBody(BodyTerm t) {
        for (BodyStep s : t.steps()) {
            if (!of(s)) {
                return false;
            }
        }
        return true;
    }

    @Override
    public Boolean visitPlan(PlanTerm t) {
        return of(t.label()) && of(t.trigger().literal()) && of(t.context()) && of(t.body());
    }

    @Override
    public Boolean visitObject(ObjectTerm t) {
        return t.value() == null || VALUES.get(t.value().getClass());
    }

    /**
     * {@return whether objects of the type cannot change: a string, a boxed primitive, an enum, or a
     * record whose components are all of such types (a few levels deep)}
     */
    private static boolean isValue(Class<?> type, int depth) {
        if (type.isPrimitive() || type == String.class || type == Boolean.class || type == Character.class
                || type == Integer.class || type == Long.class || type == Double.class || type == Float.class
                || type == Short.class || type == Byte.class || type.isEnum()) {
            return true;
        }
        if (!type.isRecord() || depth > 4) {
            return false;
        }
        for (RecordComponent c : type.getRecordComponents()) {
            if (!isValue(c.getType(), depth + 1)) {
                return false;
            }
        }
        return true;
    }
}
