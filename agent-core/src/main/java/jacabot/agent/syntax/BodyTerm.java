package jacabot.agent.syntax;

import java.util.List;
import java.util.StringJoiner;
import java.util.function.Consumer;

/** A plan body, as a sequence of steps; as a term it is written in braces: {@code { a; !g }}. */
public record BodyTerm(List<BodyStep> steps) implements Term {
    public static final BodyTerm EMPTY = new BodyTerm(List.of());

    public BodyTerm {
        steps = List.copyOf(steps);
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
        return "{ " + bodyText() + " }";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitBody(this);
    }
}
