package jacabot.agent.syntax;

/** A relational expression: comparison, unification ({@code =}) or {@code =..}. */
public record RelExpr(Op op, Term left, Term right) implements OperatorExpr {

    /** Relational operators, with Jason's printed forms. */
    public enum Op {
        LT(" < "), LTE(" <= "), GT(" > "), GTE(" >= "), EQ(" == "), DIF(" \\== "), UNIFY(" = "), UNIV(" =.. ");

        private final String symbol;

        Op(String symbol) {
            this.symbol = symbol;
        }

        @Override
        public String toString() {
            return symbol;
        }
    }

    @Override
    public String toString() {
        return "(" + left + op + right + ")";
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitRel(this);
    }
}
