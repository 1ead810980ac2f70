package jacabot.agent.syntax;

import java.util.List;
import java.util.Objects;

/** Jason's standard order of terms, and a few printing helpers. */
public final class TermOrder {
    private TermOrder() {
    }

    private static int rank(Term t) {
        if (t instanceof NumberTerm) {
            return 0;
        }
        if (t instanceof StringTerm) {
            return 1;
        }
        if (t instanceof ListTerm) {
            return 2;
        }
        if (t instanceof Literal) {
            return 3;
        }
        if (t instanceof Var) {
            return 5;
        }
        return 4;
    }

    /**
     * Jason's order of numbers: by {@code >} and {@code <}, so NaN is neither before nor after any
     * number (a NaN in {@code .sort} stays where it is; {@code NaN >= 3} holds) and -0 equals 0.
     */
    private static int compareNumbers(double x, double y) {
        return x > y ? 1 : x < y ? -1 : 0;
    }

    public static int compare(Term a, Term b) {
        int ra = rank(a);
        int rb = rank(b);
        if (ra != rb) {
            return Integer.compare(ra, rb);
        }
        switch (ra) {
            case 0:
                return compareNumbers(((NumberTerm) a).value(), ((NumberTerm) b).value());
            case 1:
                return ((StringTerm) a).value().compareTo(((StringTerm) b).value());
            case 2:
                return compareLists((ListTerm) a, (ListTerm) b);
            case 3:
                return compareLiterals((Literal) a, (Literal) b);
            case 5:
                return a.toString().compareTo(b.toString());
            default:
                return a.toString().compareTo(b.toString());
        }
    }

    private static int compareLists(ListTerm a, ListTerm b) {
        Term x = a;
        Term y = b;
        while (x instanceof ListTerm.Cons cx && y instanceof ListTerm.Cons cy) {
            int c = compare(cx.head(), cy.head());
            if (c != 0) {
                return c;
            }
            x = cx.tail();
            y = cy.tail();
        }
        if (x instanceof ListTerm.Empty && y instanceof ListTerm.Empty) {
            return 0;
        }
        if (x instanceof ListTerm.Empty) {
            return -1;
        }
        if (y instanceof ListTerm.Empty) {
            return 1;
        }
        return compare(x, y);
    }

    private static int compareLiterals(Literal a, Literal b) {
        if (a.ns() != b.ns() && !Objects.equals(a.ns(), b.ns())) {
            int n = compare(a.nsTerm(), b.nsTerm()); // Jason orders by namespace first
            if (n != 0) {
                return n;
            }
        }
        int c = a.functor().compareTo(b.functor());
        if (c != 0) {
            return c;
        }
        if (a.negated() != b.negated()) {
            return a.negated() ? 1 : -1;
        }
        c = compareSeq(a.args(), b.args());
        if (c != 0) {
            return c;
        }
        c = compareSeq(a.annots(), b.annots());
        if (c != 0 || a.tail() == b.tail()) {
            return c;
        }
        // as Jason orders them: d, d[|T], d[a], d[a|T]
        return a.tail() == null ? -1 : b.tail() == null ? 1 : compare(a.tail(), b.tail());
    }

    private static int compareSeq(List<Term> a, List<Term> b) {
        int n = Math.min(a.size(), b.size());
        for (int i = 0; i < n; i++) {
            int c = compare(a.get(i), b.get(i));
            if (c != 0) {
                return c;
            }
        }
        return Integer.compare(a.size(), b.size());
    }

    /** Appends terms separated by commas, with no spaces, as Jason prints arguments. */
    public static void join(StringBuilder sb, List<? extends Term> terms) {
        for (int i = 0; i < terms.size(); i++) {
            if (i > 0) {
                sb.append(',');
            }
            sb.append(terms.get(i));
        }
    }
}
