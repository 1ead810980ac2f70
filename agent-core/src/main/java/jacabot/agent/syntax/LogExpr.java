package jacabot.agent.syntax;

/** A logical expression: {@code a & b}, {@code a | b} or {@code not a}. */
public record LogExpr(Op op, Term left, Term right) implements OperatorExpr {

    /** Logical operators. */
    public enum Op { AND, OR, NOT }

    public static LogExpr not(Term operand) {
        return new LogExpr(Op.NOT, operand, null);
    }

    @Override
    public String toString() {
        switch (op) {
            case NOT: return "not (" + left + ")";
            case AND: return "(" + left + " & " + right + ")";
            default: return "(" + left + " | " + right + ")";
        }
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitLog(this);
    }
}
