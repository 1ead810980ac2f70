package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A plan used as a term, e.g. an argument of {@code .add_plan}. */
public record PlanTerm(Plan plan) implements Term {
    @Override
    public boolean isGround() {
        return false;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        plan.trigger().literal().collectVars(sink);
    }

    @Override
    public String toString() {
        String s = plan.toString();
        return "{ " + s.substring(0, s.length() - 1) + " }";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitPlan(this);
    }
}
