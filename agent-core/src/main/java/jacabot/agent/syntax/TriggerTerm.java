package jacabot.agent.syntax;

import java.util.function.Consumer;

/**
 * A trigger used as a term, as in {@code .wait({+b})}; a bare one prints without braces, as
 * Jason prints a plan's trigger ({@code .relevant_plan(T, P)}).
 */
public record TriggerTerm(Trigger trigger, boolean bare) implements Term {
    public TriggerTerm(Trigger trigger) {
        this(trigger, false);
    }

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
        return bare ? trigger.toString() : "{ " + trigger + " }";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitTrigger(this);
    }

    /** Equal by the trigger, printed bare or not. */
    @Override
    public boolean equals(Object o) {
        return o instanceof TriggerTerm t && t.trigger.equals(trigger);
    }

    @Override
    public int hashCode() {
        return trigger.hashCode();
    }
}
