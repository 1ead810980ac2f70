package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A logical expression: {@code a & b}, {@code a | b} or {@code not a}. */
public record LogExpr(Op op, Term left, Term right) implements Term {

    /** Logical operators. */
    public enum Op { AND, OR, NOT }

    public static LogExpr not(Term operand) {
        return new LogExpr(Op.NOT, operand, null);
    }

    @Override
    public boolean isGround() {
        return left.isGround() && (right == null || right.isGround());
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        left.collectVars(sink);
        if (right != null) {
            right.collectVars(sink);
        }
    }

    @Override
    public String toString() {
        switch (op) {
            case NOT: return "not (" + left + ")";
            case AND: return "(" + left + " & " + right + ")";
            default: return "(" + left + " | " + right + ")";
        }
    }
}
