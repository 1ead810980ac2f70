package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A Java object carried as a term (e.g. an artifact id); equal when the objects are equal. */
public record ObjectTerm(Object value) implements Term {
    @Override
    public boolean isGround() {
        return true;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
    }

    @Override
    public String toString() {
        return String.valueOf(value);
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitObject(this);
    }
}
