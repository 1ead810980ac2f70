package jacabot.agent.syntax;

import java.util.List;
import java.util.function.Consumer;

/**
 * A variable with annotations, {@code P[error(E)]} or {@code _[source(ag)]}, or with a namespace,
 * {@code ns::X} or {@code NS::X}: it stands for a literal that has (at least) these annotations
 * and is in that namespace, as Jason's annotated {@code VarTerm}. With a tail, {@code P[H|T]},
 * the tail takes the literal's other annotations. The variable itself takes the literal without
 * its annotations and in the default namespace; the namespace is the prefix's to hold.
 *
 * @param tail null, or the variable after {@code |} in the annotations
 * @param ns null, or the namespace (an atom or a variable) written before the variable
 */
public record AnnotatedVar(Var var, List<Term> annots, Term tail, Term ns) implements Term {
    public AnnotatedVar {
        annots = List.copyOf(annots);
        if (ns instanceof Literal l && l.isDefaultNsName()) {
            ns = null;
        }
    }

    public AnnotatedVar(Var var, List<Term> annots, Term tail) {
        this(var, annots, tail, null);
    }

    public AnnotatedVar(Var var, List<Term> annots) {
        this(var, annots, null, null);
    }

    /** {@return the term the variable's value stands for: the value with these annotations and in this namespace} */
    public Term wrap(Term value, List<Term> appliedAnnots, Term appliedNs) {
        if (!(value instanceof Literal l)) {
            return value;
        }
        l = l.addAnnots(appliedAnnots);
        return ns == null ? l : l.withNs(appliedNs);
    }

    @Override
    public boolean isGround() {
        return false;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        if (ns != null) {
            ns.collectVars(sink);
        }
        sink.accept(var);
        annots.forEach(a -> a.collectVars(sink));
        if (tail != null) {
            tail.collectVars(sink);
        }
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitAnnotatedVar(this);
    }

    @Override
    public String toString() {
        var sb = new StringBuilder();
        if (ns != null) {
            sb.append(ns).append("::");
        }
        sb.append(var);
        if (annots.isEmpty() && tail == null) {
            return sb.toString();
        }
        sb.append('[');
        TermOrder.join(sb, annots);
        if (tail != null) {
            sb.append('|').append(tail);
        }
        return sb.append(']').toString();
    }
}
