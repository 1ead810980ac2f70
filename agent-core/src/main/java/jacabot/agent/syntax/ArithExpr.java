package jacabot.agent.syntax;

/** An arithmetic expression; evaluated to a {@link NumberTerm} once its variables are bound. */
public record ArithExpr(Op op, Term left, Term right) implements OperatorExpr {

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
    public static ArithExpr unary(Op op, Term operand) {
        return new ArithExpr(op, operand, null);
    }

    public boolean isUnary() {
        return right == null;
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
