package jacabot.cartago.bridge;

import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.cartago.AgentId;
import java.lang.reflect.Array;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;

/** Converts between AgentSpeak terms and the plain Java values artifacts use, as JaCa does. */
public final class TermConverter {
    private TermConverter() {
    }

    /** A term as an operation argument: numbers as Double, strings and atoms as String, lists as List. */
    public static Object toJava(Term t) {
        if (t instanceof NumberTerm n) {
            return n.value();
        }
        if (t instanceof StringTerm s) {
            return s.value();
        }
        if (t instanceof ObjectTerm o) {
            return o.value();
        }
        if (t instanceof ListTerm l) {
            var out = new ArrayList<Object>();
            for (Term e : l.elements()) {
                out.add(toJava(e));
            }
            return out;
        }
        if (t instanceof Literal l && l.isAtom()) {
            if (l.functor().equals("true") || l.functor().equals("false")) {
                return Boolean.valueOf(l.functor());
            }
            return l.functor();
        }
        return t.toString();
    }

    /** A Java value as a term: numbers, strings, booleans (atoms), lists and arrays, ids. */
    public static Term toTerm(Object v) {
        if (v == null) {
            return Literal.atom("null");
        }
        if (v instanceof Term t) {
            return t;
        }
        if (v instanceof Number n) {
            return new NumberTerm(n.doubleValue());
        }
        if (v instanceof String s) {
            return new StringTerm(s);
        }
        if (v instanceof Character c) {
            return new StringTerm(c.toString());
        }
        if (v instanceof Boolean b) {
            return b ? Literal.TRUE : Literal.FALSE;
        }
        if (v instanceof Enum<?> e) {
            return Literal.atom(e.name().toLowerCase(Locale.ROOT));
        }
        if (v instanceof AgentId a) {
            return Literal.atom(a.name());
        }
        if (v instanceof Collection<?> c) {
            var items = new ArrayList<Term>();
            for (Object o : c) {
                items.add(toTerm(o));
            }
            return ListTerm.of(items);
        }
        if (v.getClass().isArray()) {
            var items = new ArrayList<Term>();
            for (int i = 0; i < Array.getLength(v); i++) {
                items.add(toTerm(Array.get(v, i)));
            }
            return ListTerm.of(items);
        }
        return new ObjectTerm(v);
    }

    public static List<Term> toTerms(List<Object> values) {
        Term[] out = new Term[values.size()];
        int i = 0;
        for (Object o : values) {
            out[i++] = toTerm(o);
        }
        return List.of(out); // immutable: a literal keeps it as it is (every percept update makes one)
    }
}
