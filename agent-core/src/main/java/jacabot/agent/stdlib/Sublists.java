package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;

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
        var out = new ArrayList<Unifier>();
        for (Term part : parts(args[1])) {
            Unifier c = un.copy();
            if (c.unifies(args[0], part)) { // a string part never unifies with a list P, nor a list with a string
                out.add(c);
            }
        }
        return out.iterator();
    }

    /** The candidates in Jason's order. */
    private List<Term> parts(Term whole) {
        var out = new ArrayList<Term>();
        if (whole instanceof StringTerm s) {
            String v = s.value();
            for (int n = v.length(); n >= 0; n--) {
                out.add(new StringTerm(kind == Kind.PREFIX ? v.substring(0, n) : v.substring(v.length() - n)));
            }
            return out;
        }
        List<Term> items = ((ListTerm) whole).elements();
        int size = items.size();
        switch (kind) {
            case PREFIX -> {
                for (int n = size; n >= 0; n--) {
                    out.add(listOf(items.subList(0, n)));
                }
            }
            case SUFFIX -> {
                for (int n = size; n >= 0; n--) {
                    out.add(listOf(items.subList(size - n, size)));
                }
            }
            case SUBLIST -> {
                for (int from = 0; from < size; from++) {
                    for (int to = size; to > from; to--) {
                        out.add(listOf(items.subList(from, to)));
                    }
                }
                out.add(listOf(List.of()));
            }
        }
        return out;
    }
}
