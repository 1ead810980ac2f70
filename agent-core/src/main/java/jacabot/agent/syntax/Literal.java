package jacabot.agent.syntax;

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import java.util.RandomAccess;
import java.util.function.Consumer;

/**
 * A literal: an atom, a structure {@code f(t1,...,tn)}, with optional annotations
 * {@code [a1,...]} and strong negation {@code ~}. Annotations are kept sorted and without
 * duplicates, as Jason keeps them. Atoms are literals with no arguments and no annotations.
 * A literal lives in a namespace ({@code ns::b(1)}, Jason's modules): null stands for the default
 * namespace, otherwise it is an atom or a variable ({@code NS::b}); {@code b} and {@code ns::b}
 * are different predicates. As in Jason, the annotations may end with a tail variable,
 * {@code b[x|T]} or {@code b[|T]}: it takes the annotations a matching literal has beyond these.
 *
 * @param tail null (nearly always), or what follows {@code |} in the annotations: a variable, or a
 *        list whose elements join the annotations (its own tail, if any, becomes the tail)
 * @param src where the literal was written (null: made at run time); as Jason's, it goes with the
 *        literal through unifiers, beliefs and messages ({@code .get_src_info}) and counts for
 *        nothing else (equality, order, printing)
 */
public record Literal(String functor, List<Term> args, List<Term> annots, boolean negated, boolean operandAtom, Term ns,
        Term tail, SourceInfo src) implements Term {

    public static final Literal DEFAULT_NS = new Literal("default", List.of(), List.of(), false, false, null);
    public static final Literal TRUE = atom("true");
    public static final Literal FALSE = atom("false");
    public static final Literal SELF = atom("self");
    public static final Literal SOURCE_SELF = of("source", SELF);
    public static final Literal SOURCE_PERCEPT = of("source", atom("percept"));
    /** The annotations {@code [source(self)]}. */
    private static final List<Term> SOURCE_SELF_ONLY = List.of(SOURCE_SELF);
    /** The functor of a rule used as a term, {@code { head :- body }}: {@code rule__(head, body)}. */
    public static final String RULE_TERM = "rule__";
    /** The name of the default namespace, as a term ({@code default::b} is {@code b}). */
    public static final String DEFAULT_NS_NAME = "default";
    /** Jason's prefix of the unique names given to local namespaces ({@code #3priv}). */
    public static final String LOCAL_NS_PREFIX = "#";

    /**
     * @param operandAtom an atom written as an operand of a relational expression ({@code Z = a}),
     *        which Jason's parser makes a structure rather than an atom: only {@code .structure}
     *        tells them apart, the flag counts for nothing else (equality, order, printing)
     */
    public Literal {
        args = List.copyOf(args);
        if (tail != null) {
            // out of line: the constructor of every literal stays small enough to be inlined
            annots = annotsWithTail(annots, tail);
            tail = tailEnd(tail);
            operandAtom = false;
        }
        annots = annots.isEmpty() ? List.of() : sortAnnots(annots);
        operandAtom = operandAtom && args.isEmpty() && annots.isEmpty() && !negated;
        if (ns instanceof Literal l && l.isDefaultNsName()) {
            ns = null; // default::b is b
        }
    }

    public Literal(String functor, List<Term> args, List<Term> annots, boolean negated, boolean operandAtom, Term ns,
            Term tail) {
        this(functor, args, annots, negated, operandAtom, ns, tail, null);
    }

    public Literal(String functor, List<Term> args, List<Term> annots, boolean negated, boolean operandAtom, Term ns) {
        this(functor, args, annots, negated, operandAtom, ns, null, null);
    }

    public Literal(String functor, List<Term> args, List<Term> annots, boolean negated, boolean operandAtom) {
        this(functor, args, annots, negated, operandAtom, null, null, null);
    }

    public Literal(String functor, List<Term> args, List<Term> annots, boolean negated) {
        this(functor, args, annots, negated, false, null, null, null);
    }

    /** {@return the same literal, written at {@code where}} */
    public Literal at(SourceInfo where) {
        return new Literal(functor, args, annots, negated, operandAtom, ns, tail, where);
    }

    /** {@return this atom as written in a relational expression (see {@link #operandAtom})} */
    public Literal asOperandAtom() {
        return isAtom() && !operandAtom ? new Literal(functor, args, annots, negated, true, ns, null, src) : this;
    }

    /** {@return the same literal in namespace {@code newNs} (null or {@code default}: the default one)} */
    public Literal withNs(Term newNs) {
        if (newNs instanceof Literal l && l.isDefaultNsName()) {
            newNs = null;
        }
        return Objects.equals(newNs, ns) ? this : new Literal(functor, args, annots, negated, operandAtom, newNs, tail, src);
    }

    /** {@return the namespace as a term: the atom {@code default} for the default namespace} */
    public Term nsTerm() {
        return ns == null ? DEFAULT_NS : ns;
    }

    /** {@return whether the literal is in the default namespace} */
    public boolean inDefaultNs() {
        return ns == null;
    }

    /** {@return whether this is the atom {@code default}, the default namespace's name} */
    public boolean isDefaultNsName() {
        return isAtom() && ns == null && functor.equals(DEFAULT_NS_NAME);
    }

    /** {@return whether this atom names a local namespace ({@code #3priv}), which no variable may take} */
    public boolean isLocalNsName() {
        return isAtom() && functor.startsWith(LOCAL_NS_PREFIX);
    }

    public static Literal atom(String functor) {
        return new Literal(functor, List.of(), List.of(), false);
    }

    public static Literal of(String functor, Term... args) {
        return new Literal(functor, List.of(args), List.of(), false);
    }

    public static Literal of(String functor, List<Term> args) {
        return new Literal(functor, args, List.of(), false);
    }

    /** {@return the annotations with the elements of a tail bound to a list} */
    private static List<Term> annotsWithTail(List<Term> annots, Term tail) {
        if (!(tail instanceof ListTerm)) {
            return annots;
        }
        var all = new ArrayList<Term>(annots);
        Term t = tail;
        while (t instanceof ListTerm.Cons c) {
            all.add(c.head());
            t = c.tail();
        }
        return all;
    }

    /** {@return the tail that is left: a list's own tail, or null for a list ending in []} */
    private static Term tailEnd(Term tail) {
        Term t = tail;
        while (t instanceof ListTerm.Cons c) {
            t = c.tail();
        }
        return t instanceof ListTerm ? null : t;
    }

    private static List<Term> sortAnnots(List<Term> annots) {
        if (annots == SOURCE_SELF_ONLY || annots instanceof Presorted) {
            return annots; // the agent's own beliefs and goals, or a list checked once: nothing to check
        }
        if (isSortedSet(annots)) {
            return List.copyOf(annots);
        }
        var sorted = new ArrayList<Term>(annots);
        Collections.sort(sorted);
        for (int i = sorted.size() - 1; i > 0; i--) {
            if (sorted.get(i).equals(sorted.get(i - 1))) {
                sorted.remove(i);
            }
        }
        return List.copyOf(sorted);
    }

    /**
     * {@return the annotations sorted and without duplicates, in a list that literals made with it keep
     * as it is}: for the annotations of many literals made at run time (an artifact's percepts, five
     * structured annotations each), whose pairwise comparison in every literal's constructor was
     * about 3 % of the agent's thread in experiment 4. The list is immutable, and equal to (and
     * hashed as) any list of the same terms.
     */
    public static List<Term> presortedAnnots(List<Term> annots) {
        List<Term> sorted = annots.isEmpty() ? List.of() : sortAnnots(annots);
        return sorted.isEmpty() || sorted instanceof Presorted ? sorted : new Presorted(sorted);
    }

    /** Annotations checked sorted once ({@link #presortedAnnots}): an immutable view of an immutable list. */
    private static final class Presorted extends AbstractList<Term> implements RandomAccess {
        private final List<Term> terms;

        Presorted(List<Term> terms) {
            this.terms = terms;
        }

        @Override
        public Term get(int i) {
            return terms.get(i);
        }

        @Override
        public int size() {
            return terms.size();
        }
    }

    private static boolean isSortedSet(List<Term> annots) {
        for (int i = 1, n = annots.size(); i < n; i++) {
            if (annots.get(i - 1).compareTo(annots.get(i)) >= 0) {
                return false;
            }
        }
        return true;
    }

    // written out, with the values the record's would have: beliefs and annotations are compared
    // and hashed all the time, and the generated methods are slow until compiled
    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof Literal l && negated == l.negated && functor.equals(l.functor)
                && args.equals(l.args) && annots.equals(l.annots) && Objects.equals(ns, l.ns)
                && (tail == l.tail || tail != null && tail.equals(l.tail));
    }

    @Override
    public int hashCode() {
        int h = ((functor.hashCode() * 31 + args.hashCode()) * 31 + annots.hashCode()) * 31 + Boolean.hashCode(negated);
        if (ns != null) {
            h = h * 31 + ns.hashCode();
        }
        return tail == null ? h : h * 31 + tail.hashCode();
    }

    public int arity() {
        return args.size();
    }

    public Term arg(int i) {
        return args.get(i);
    }

    /** {@return whether this is a plain atom (no arguments, annotations or negation)} */
    public boolean isAtom() {
        return args.isEmpty() && annots.isEmpty() && !negated && tail == null;
    }

    /** {@return whether the functor names an internal action ({@code .print}, {@code jia.f})} */
    public boolean isInternalAction() {
        return functor.indexOf('.') >= 0 && functor.charAt(0) != '\'';
    }

    /** {@return the literal with these annotations (the tail, if any, kept)} */
    public Literal withAnnots(List<Term> newAnnots) {
        return new Literal(functor, args, newAnnots, negated, false, ns, tail, src);
    }

    public Literal withArgs(List<Term> newArgs) {
        return new Literal(functor, newArgs, annots, negated, false, ns, tail, src);
    }

    /** {@return the literal with no annotations and no tail} */
    public Literal withoutAnnots() {
        return annots.isEmpty() && tail == null ? this : new Literal(functor, args, List.of(), negated, false, ns, null, src);
    }

    /** {@return this literal without its {@code source(_)} annotations} */
    public Literal withoutSources() {
        return withAnnots(annots.stream().filter(a -> !(a instanceof Literal l && l.functor.equals("source") && l.args.size() == 1)).toList());
    }

    public Literal addAnnots(List<Term> more) {
        if (more.isEmpty()) {
            return this;
        }
        var all = new ArrayList<Term>(annots);
        all.addAll(more);
        return withAnnots(all);
    }

    /** {@return a literal with these arguments annotated {@code [source(self)]} only (a belief or goal of the agent's own)} */
    public Literal withArgsFromSelf(List<Term> newArgs) {
        return new Literal(functor, newArgs, SOURCE_SELF_ONLY, negated, false, ns, null, src);
    }

    public Literal addAnnot(Term annot) {
        int n = annots.size();
        if (n == 0) {
            // source(self) on a subgoal or a belief of the agent's own: a list shared by all
            return new Literal(functor, args, annot == SOURCE_SELF ? SOURCE_SELF_ONLY : List.of(annot), negated, false, ns, tail, src);
        }
        // one insertion into the sorted annotations, without re-sorting them
        int lo = 0;
        int hi = n;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            int c = annots.get(mid).compareTo(annot);
            if (c == 0) {
                return this;
            }
            if (c < 0) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        Term[] out = new Term[n + 1];
        for (int i = 0; i < lo; i++) {
            out[i] = annots.get(i);
        }
        out[lo] = annot;
        for (int i = lo; i < n; i++) {
            out[i + 1] = annots.get(i);
        }
        return new Literal(functor, args, List.of(out), negated, false, ns, tail, src);
    }

    /** {@return the first annotation with this functor, or null} */
    public Literal getAnnot(String annotFunctor) {
        for (int i = 0, n = annots.size(); i < n; i++) {
            if (annots.get(i) instanceof Literal l && l.functor.equals(annotFunctor)) {
                return l;
            }
        }
        return null;
    }

    /** {@return whether some annotation is {@code source(_)}} */
    public boolean hasSource() {
        return getAnnot("source") != null;
    }

    /** {@return the same namespace, functor, arity and negation (the belief base's key)} */
    public boolean samePredicate(Literal o) {
        return sameName(o) && Objects.equals(ns, o.ns);
    }

    /** {@return the same functor, arity and negation, whatever the namespaces} */
    public boolean sameName(Literal o) {
        return negated == o.negated && args.size() == o.args.size() && functor.equals(o.functor);
    }

    @Override
    public boolean isGround() {
        if (tail != null) {
            return false;
        }
        if (ns != null && !ns.isGround()) {
            return false;
        }
        for (int i = 0, n = args.size(); i < n; i++) {
            if (!args.get(i).isGround()) {
                return false;
            }
        }
        for (int i = 0, n = annots.size(); i < n; i++) {
            if (!annots.get(i).isGround()) {
                return false;
            }
        }
        return true;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        // annotations first, as Jason renames a literal's variables (so renamed ones get its numbers)
        for (Term t : annots) {
            t.collectVars(sink);
        }
        if (tail != null) {
            tail.collectVars(sink);
        }
        for (Term t : args) {
            t.collectVars(sink);
        }
        if (ns != null) {
            ns.collectVars(sink);
        }
    }

    @Override
    public String toString() {
        if (functor.equals(RULE_TERM) && args.size() == 2 && annots.isEmpty() && tail == null) {
            return "{ " + args.get(0) + " :- " + args.get(1) + " }"; // as Jason prints a rule as a term
        }
        var sb = new StringBuilder();
        if (ns != null) {
            sb.append(ns).append("::"); // as Jason: ns::~b
        }
        if (negated) {
            sb.append('~');
        }
        sb.append(functor);
        if (!args.isEmpty()) {
            sb.append('(');
            TermOrder.join(sb, args);
            sb.append(')');
        }
        if (!annots.isEmpty() || tail != null) {
            sb.append('[');
            TermOrder.join(sb, annots);
            if (tail != null) {
                sb.append('|').append(tail); // as Jason: b[x|T], b[|T]
            }
            sb.append(']');
        }
        return sb.toString();
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitLiteral(this);
    }
}
