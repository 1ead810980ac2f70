package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A trigger used as a term, as in {@code .wait({+b})}. */
public record TriggerTerm(Trigger trigger) implements Term {
    @Override
    public boolean isGround() {
        return trigger.literal().isGround();
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        trigger.literal().collectVars(sink);
    }

    @Override
    public String toString() {
        return "{ " + trigger + " }";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitTrigger(this);
    }
}
