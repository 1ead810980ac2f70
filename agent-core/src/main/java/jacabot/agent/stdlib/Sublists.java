package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;

/**
 * {@code .prefix(P, L)}, {@code .suffix(S, L)} and {@code .sublist(S, L)}: P (S) unifies with a
 * prefix (suffix, contiguous part) of the list L, one solution each, longest first and the empty
 * one last, as Jason enumerates them; prefix and suffix also take a string L.
 */
final class Sublists extends DefaultInternalAction {
    private enum Kind { PREFIX, SUFFIX, SUBLIST }

    private final Kind kind;

    private Sublists(String name, Kind kind) {
        super(name, 2, 2);
        this.kind = kind;
    }

    static Sublists prefix() {
        return new Sublists(".prefix", Kind.PREFIX);
    }

    static Sublists suffix() {
        return new Sublists(".suffix", Kind.SUFFIX);
    }

    static Sublists sublist() {
        return new Sublists(".sublist", Kind.SUBLIST);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String ia = name().substring(1);
        boolean strings = kind != Kind.SUBLIST;
        if (!(args[1] instanceof ListTerm || strings && args[1] instanceof StringTerm)) {
            throw new IaException("wrong_arguments", "Wrong argument for internal action '" + ia + "': second argument must be "
                    + (strings ? "either a list or a string" : "a list"));
        }
        boolean free = args[0] instanceof Var || args[0] instanceof AnnotatedVar;
        if (!(free || args[0] instanceof ListTerm || strings && args[0] instanceof StringTerm)) {
            throw new IaException("wrong_arguments", "Wrong argument for internal action '" + ia + "': first argument must be "
                    + (strings ? "a list, string, or a variable" : "a list or a variable"));
        }
        // lazy: .sublist of a long list has a quadratic number of parts, and a test needs the first
        return new Parts(un, args[0], args[1]);
    }

    /** The candidates in Jason's order, each made only when the previous did not unify. */
    private final class Parts implements Iterator<Unifier> {
        private final Unifier un;
        private final Term x;
        private final String text;
        private final List<Term> items;
        private final int size;
        /** The next candidate: [from, to) of the list or string; from == to is the empty one, the last. */
        private int from;
        private int to;
        private boolean done;
        private Unifier pending;

        Parts(Unifier un, Term x, Term whole) {
            this.un = un;
            this.x = x;
            this.text = whole instanceof StringTerm s ? s.value() : null;
            this.items = text == null ? ((ListTerm) whole).elements() : null;
            this.size = text != null ? text.length() : items.size();
            this.to = size;
        }

        @Override
        public boolean hasNext() {
            while (pending == null && !done) {
                Term part = text != null ? new StringTerm(text.substring(from, to)) : listOf(items.subList(from, to));
                step();
                Unifier c = un.copy();
                if (c.unifies(x, part)) { // a string part never unifies with a list, nor a list with a string
                    pending = c;
                }
            }
            return pending != null;
        }

        /** Moves to the next candidate: prefixes shrink at the end, suffixes at the start, sublists both. */
        private void step() {
            if (from == to) {
                done = true; // the empty part comes last
                return;
            }
            switch (kind) {
                case PREFIX -> to--;
                case SUFFIX -> from++;
                case SUBLIST -> {
                    if (to > from + 1) {
                        to--;
                    } else if (from + 1 < size) {
                        from++;
                        to = size;
                    } else {
                        from = size; // the empty one
                        to = size;
                    }
                }
            }
        }

        @Override
        public Unifier next() {
            if (!hasNext()) {
                throw new NoSuchElementException();
            }
            Unifier u = pending;
            pending = null;
            return u;
        }
    }
}
