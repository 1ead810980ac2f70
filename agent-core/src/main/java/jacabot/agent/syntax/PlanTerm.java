package jacabot.agent.syntax;

import java.util.Objects;
import java.util.function.Consumer;

/**
 * A plan used as a term, {@code { @L +!g : C <- B }}: its label, context and body may be
 * variables, so that plan terms unify with the plans of a library (Jason's {@code Plan} is a
 * structure {@code plan(Label, Trigger, Context, Body)}).
 *
 * @param label   null, a literal or a variable
 * @param context null (true), or a formula, or a variable
 * @param body    a {@link BodyTerm} or a variable
 * @param bare    whether it prints as Jason prints a plan, {@code @L +!g <- B.}, not in braces
 *                (the plan {@code .relevant_plan} gives)
 */
public record PlanTerm(Term label, Trigger trigger, Term context, Term body, SourceInfo source, boolean bare) implements Term {

    /** A plan's body taken out of it ({@code {@L +!g <- B}}) prints bare, as Jason's: {@code a; b}. */
    public PlanTerm {
        if (body instanceof BodyTerm b && b.braced()) {
            body = new BodyTerm(b.steps(), false);
        }
    }

    public PlanTerm(Term label, Trigger trigger, Term context, Term body, SourceInfo source) {
        this(label, trigger, context, body, source, false);
    }

    public PlanTerm(Plan p) {
        this(p.label(), p.trigger(), p.context(), p.body(), p.source());
    }

    /** {@return the same plan term, printed as a plan or in braces} */
    public PlanTerm printedBare(boolean asPlan) {
        return new PlanTerm(label, trigger, context, body, source, asPlan);
    }

    /** {@return the plan this term describes} @throws IllegalArgumentException when a part is unbound */
    public Plan toPlan() {
        Literal l;
        if (label == null || label instanceof Var) {
            l = null;
        } else if (label instanceof Literal lit) {
            l = lit;
        } else {
            throw new IllegalArgumentException("the label of " + this + " is not a literal");
        }
        if (!(body instanceof BodyTerm b)) {
            throw new IllegalArgumentException("the body of " + this + " is unbound");
        }
        return new Plan(l, trigger, context, b, source);
    }

    /** {@return the context, {@code true} when there is none} */
    public Term contextOrTrue() {
        return context == null ? Literal.TRUE : context;
    }

    @Override
    public boolean isGround() {
        return (label == null || label.isGround()) && trigger.literal().isGround()
                && (context == null || context.isGround()) && body.isGround();
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        if (label != null) {
            label.collectVars(sink);
        }
        trigger.literal().collectVars(sink);
        if (context != null) {
            context.collectVars(sink);
        }
        body.collectVars(sink);
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitPlan(this);
    }

    @Override
    public String toString() {
        var out = new StringBuilder(bare ? "" : "{ ");
        if (label != null) {
            out.append('@').append(label).append(' ');
        }
        out.append(trigger);
        if (context != null) {
            out.append(" : ").append(context);
        }
        if (body instanceof BodyTerm b) {
            if (!b.steps().isEmpty()) {
                out.append(" <- ").append(b.bodyText());
            }
        } else {
            out.append(" <- ").append(body);
        }
        return out.append(bare ? "." : " }").toString();
    }

    /** Plans as terms are equal by their parts (a missing context is {@code true}), wherever written. */
    @Override
    public boolean equals(Object o) {
        return o instanceof PlanTerm p && Objects.equals(p.label, label) && p.trigger.equals(trigger)
                && p.contextOrTrue().equals(contextOrTrue()) && p.body.equals(body);
    }

    @Override
    public int hashCode() {
        return Objects.hash(label, trigger, contextOrTrue(), body);
    }
}
