package jacabot.agent.syntax;

/**
 * An arithmetic expression; evaluated to a {@link NumberTerm} once its variables are bound. Its
 * source is where it was written, for Jason's warning when an operand is not a number; it takes no
 * part in equality.
 */
public record ArithExpr(Op op, Term left, Term right, SourceInfo src) implements OperatorExpr {

    /** Arithmetic operators, with Jason's printed forms. */
    public enum Op {
        PLUS("+"), MINUS("-"), TIMES("*"), DIV("/"), INTDIV(" div "), MOD(" mod "), POW("**");

        private final String symbol;

        Op(String symbol) {
            this.symbol = symbol;
        }

        public double apply(double x, double y) {
            switch (this) {
                case PLUS: return x + y;
                case MINUS: return x - y;
                case TIMES: return x * y;
                case DIV: return x / y;
                case INTDIV: return (int) x / (int) y;
                case MOD: return x % y;
                default: return Math.pow(x, y);
            }
        }

        @Override
        public String toString() {
            return symbol;
        }
    }

    /** A unary expression ({@code -X}, {@code +X}). */
    public static ArithExpr unary(Op op, Term operand, SourceInfo src) {
        return new ArithExpr(op, operand, null, src);
    }

    /** {@return the same expression over other operands, written at the same place} */
    public ArithExpr with(Term left, Term right) {
        return new ArithExpr(op, left, right, src);
    }

    public boolean isUnary() {
        return right == null;
    }

    @Override
    public boolean equals(Object o) {
        return o == this || o instanceof ArithExpr e && op == e.op && left.equals(e.left) && java.util.Objects.equals(right, e.right);
    }

    @Override
    public int hashCode() {
        return (op.hashCode() * 31 + left.hashCode()) * 31 + java.util.Objects.hashCode(right);
    }

    @Override
    public String toString() {
        return isUnary() ? "(" + op + left + ")" : "(" + left + op + right + ")";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitArith(this);
    }
}
