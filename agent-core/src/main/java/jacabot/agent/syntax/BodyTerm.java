package jacabot.agent.syntax;

import java.util.List;
import java.util.StringJoiner;
import java.util.function.Consumer;

/**
 * A plan body, as a sequence of steps; as a term it is written in braces: {@code { a; !g }}.
 * A single step taken out of a body by a variable ({@code {T; _}}) is not braced: Jason prints
 * it as the bare formula ({@code !g}); bracing is only printing and does not count for equality.
 */
public record BodyTerm(List<BodyStep> steps, boolean braced) implements Term {
    public static final BodyTerm EMPTY = new BodyTerm(List.of());

    public BodyTerm {
        steps = List.copyOf(steps);
    }

    public BodyTerm(List<BodyStep> steps) {
        this(steps, true);
    }

    /** {@return the one step as a bare formula, as a variable step of a body term gets it} */
    public static BodyTerm bare(BodyStep step) {
        return new BodyTerm(List.of(step), false);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof BodyTerm b && b.steps.equals(steps);
    }

    @Override
    public int hashCode() {
        return steps.hashCode();
    }

    @Override
    public boolean isGround() {
        return steps.stream().allMatch(s -> s.term().isGround());
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        steps.forEach(s -> s.term().collectVars(sink));
    }

    /** {@return the steps joined as Jason prints a body: {@code a; b}} */
    public String bodyText() {
        var joiner = new StringJoiner("; ");
        steps.forEach(s -> joiner.add(s.toString()));
        return joiner.toString();
    }

    @Override
    public String toString() {
        return braced ? "{ " + bodyText() + " }" : bodyText();
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitBody(this);
    }
}
