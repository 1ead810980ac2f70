package jacabot.agent.syntax;

/** A Java object carried as a term (e.g. an artifact id); equal when the objects are equal. */
public record ObjectTerm(Object value) implements Term {
    @Override
    public boolean isGround() {
        return true;
    }

    @Override
    public void collectVars(java.util.function.Consumer<Var> sink) {
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
