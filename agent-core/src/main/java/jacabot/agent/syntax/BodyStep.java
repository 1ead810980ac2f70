package jacabot.agent.syntax;

/** One formula of a plan body, with the kind of deed it is and where it was written. */
public record BodyStep(Kind kind, Term term, SourceInfo source) {

    /** The kinds of plan-body formula (Jason's {@code BodyType}). */
    public enum Kind {
        ACTION(""), INTERNAL_ACTION(""), CONSTRAINT(""),
        ACHIEVE("!"), ACHIEVE_NEW_FOCUS("!!"), TEST("?"),
        ADD_BEL("+"), ADD_BEL_END("+>"), ADD_BEL_NEW_FOCUS("++"),
        DEL_BEL("-"), DEL_BEL_NEW_FOCUS("--"), DEL_ADD_BEL("-+");

        private final String prefix;

        Kind(String prefix) {
            this.prefix = prefix;
        }

        public String prefix() {
            return prefix;
        }
    }

    public BodyStep withTerm(Term newTerm) {
        return new BodyStep(kind, newTerm, source);
    }

    /** Equal steps are the same deed on the same term wherever they were written (as Jason's
     *  {@code PlanBodyImpl}): the harness counts tests by comparing body terms. */
    @Override
    public boolean equals(Object o) {
        return o instanceof BodyStep b && b.kind == kind && b.term.equals(term);
    }

    @Override
    public int hashCode() {
        return kind.hashCode() * 31 + term.hashCode();
    }

    @Override
    public String toString() {
        return kind.prefix + term;
    }
}
