package jacabot.agent.syntax;

import java.util.List;
import java.util.function.Consumer;

/**
 * A variable with annotations, {@code P[error(E)]} or {@code _[source(ag)]}: it stands for a
 * literal that has (at least) these annotations, as Jason's annotated {@code VarTerm}. With a
 * tail, {@code P[H|T]}, the tail takes the literal's other annotations.
 *
 * @param tail null, or the variable after {@code |} in the annotations
 */
public record AnnotatedVar(Var var, List<Term> annots, Term tail) implements Term {
    public AnnotatedVar {
        annots = List.copyOf(annots);
    }

    public AnnotatedVar(Var var, List<Term> annots) {
        this(var, annots, null);
    }

    @Override
    public boolean isGround() {
        return false;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
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
        var sb = new StringBuilder(var.toString()).append('[');
        TermOrder.join(sb, annots);
        if (tail != null) {
            sb.append('|').append(tail);
        }
        return sb.append(']').toString();
    }
}
