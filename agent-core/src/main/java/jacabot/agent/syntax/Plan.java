package jacabot.agent.syntax;

/**
 * A plan {@code @label trigger : context <- body}. The label is a literal whose annotations
 * hold the plan's options ({@code atomic}) and, once in a plan library, its source.
 *
 * @param context the context, or null when it is {@code true}
 */
public record Plan(Literal label, Trigger trigger, Term context, BodyTerm body, SourceInfo source) {

    public boolean isAtomic() {
        return label != null && label.getAnnot("atomic") != null;
    }

    public Plan withLabel(Literal newLabel) {
        return new Plan(newLabel, trigger, context, body, source);
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
        if (!body.steps().isEmpty()) {
            out.append(" <- ").append(body.bodyText());
        }
        return out.append('.').toString();
    }
}
