package jacabot.agent.syntax;

/**
 * A plan {@code @label trigger : context <: condition <- body}. The label is a literal whose
 * annotations hold the plan's options ({@code atomic}) and, once in a plan library, its source.
 *
 * @param context       the context, or null when it is {@code true}
 * @param goalCondition Jason 3.2's goal condition ({@code <:}), or null: the goal is achieved as
 *                      soon as it holds
 */
public record Plan(Literal label, Trigger trigger, Term context, BodyTerm body, SourceInfo source, Term goalCondition) {

    public Plan(Literal label, Trigger trigger, Term context, BodyTerm body, SourceInfo source) {
        this(label, trigger, context, body, source, null);
    }

    public boolean isAtomic() {
        return label != null && label.getAnnot("atomic") != null;
    }

    public Plan withLabel(Literal newLabel) {
        return new Plan(newLabel, trigger, context, body, source, goalCondition);
    }

    /** {@return the plan as AgentSpeak text, as Jason prints it} */
    @Override
    public String toString() {
        var out = new StringBuilder();
        if (label != null) {
            out.append('@').append(label).append(' ');
        }
        out.append(trigger);
        if (context != null) {
            out.append(" : ").append(context);
        }
        if (goalCondition != null) {
            out.append(" <: ").append(goalCondition);
        }
        if (!body.steps().isEmpty()) {
            out.append(" <- ").append(body.bodyText());
        }
        return out.append('.').toString();
    }
}
