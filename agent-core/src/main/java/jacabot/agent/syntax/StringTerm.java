package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A string; printed with its quotes when nested in a term, without them by {@code .print}. */
public record StringTerm(String value) implements Term {
    @Override
    public boolean isGround() {
        return true;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
    }

    @Override
    public String toString() {
        return "\"" + value + "\"";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitString(this);
    }
}
