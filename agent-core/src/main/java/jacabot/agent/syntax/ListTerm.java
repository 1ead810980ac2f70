package jacabot.agent.syntax;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/** A list: the empty list or a cons cell {@code [Head|Tail]} whose tail is a list or a variable. */
public sealed interface ListTerm extends Term permits ListTerm.Empty, ListTerm.Cons {

    Empty EMPTY = new Empty();

    /** The empty list {@code []}. */
    final class Empty implements ListTerm {
        private Empty() {
        }

        @Override
        public <R> R accept(TermVisitor<R> v) {
            return v.visitEmptyList(this);
        }

        @Override
        public boolean isGround() {
            return true;
        }

        @Override
        public void collectVars(Consumer<Var> sink) {
        }

        @Override
        public String toString() {
            return "[]";
        }
    }

    /** A cons cell. */
    record Cons(Term head, Term tail) implements ListTerm {
        @Override
        public <R> R accept(TermVisitor<R> v) {
            return v.visitCons(this);
        }

        @Override
        public boolean isGround() {
            Term t = this;
            while (t instanceof Cons c) {
                if (!c.head.isGround()) {
                    return false;
                }
                t = c.tail;
            }
            return t.isGround();
        }

        @Override
        public void collectVars(Consumer<Var> sink) {
            Term t = this;
            while (t instanceof Cons c) {
                c.head.collectVars(sink);
                t = c.tail;
            }
            t.collectVars(sink);
        }

        @Override
        public String toString() {
            var sb = new StringBuilder("[");
            Term t = this;
            boolean first = true;
            while (t instanceof Cons c) {
                if (!first) {
                    sb.append(',');
                }
                sb.append(c.head);
                first = false;
                t = c.tail;
            }
            if (!(t instanceof Empty)) {
                sb.append('|').append(t);
            }
            return sb.append(']').toString();
        }
    }

    static ListTerm of(List<? extends Term> items) {
        return of(items, EMPTY);
    }

    static ListTerm of(List<? extends Term> items, Term tail) {
        Term list = tail;
        for (int i = items.size() - 1; i >= 0; i--) {
            list = new Cons(items.get(i), list);
        }
        return (ListTerm) list;
    }

    static ListTerm of(Term... items) {
        return of(List.of(items));
    }

    /** {@return the elements up to a non-list tail, in a new list of the caller's} */
    default List<Term> elements() {
        int n = 0;
        for (Term t = this; t instanceof Cons c; t = c.tail) {
            n++;
        }
        var out = new ArrayList<Term>(n); // sized: a list of more than ten grew by copying
        Term t = this;
        while (t instanceof Cons c) {
            out.add(c.head);
            t = c.tail;
        }
        return out;
    }

    /** {@return whether the list ends in {@code []} rather than a variable} */
    default boolean isProper() {
        Term t = this;
        while (t instanceof Cons c) {
            t = c.tail;
        }
        return t instanceof Empty;
    }
}
