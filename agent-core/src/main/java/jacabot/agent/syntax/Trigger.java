package jacabot.agent.syntax;

/** A triggering event of a plan or an event: {@code +b}, {@code -!g}, {@code +?q}, ... */
public record Trigger(Op op, Type type, Term literal) {

    /** Addition, deletion or goal-state change. */
    public enum Op {
        ADD("+"), DEL("-"), GOAL_STATE("^");

        private final String symbol;

        Op(String symbol) {
            this.symbol = symbol;
        }

        @Override
        public String toString() {
            return symbol;
        }
    }

    /** What the event is about. */
    public enum Type {
        BELIEF(""), ACHIEVE("!"), TEST("?");

        private final String symbol;

        Type(String symbol) {
            this.symbol = symbol;
        }

        @Override
        public String toString() {
            return symbol;
        }
    }

    public boolean isGoal() {
        return type != Type.BELIEF;
    }

    public boolean isAddition() {
        return op == Op.ADD;
    }

    public boolean isAchieveGoal() {
        return type == Type.ACHIEVE;
    }

    /** {@return the literal, when the trigger's term is one (it may be a variable in a plan)} */
    public Literal asLiteral() {
        return literal instanceof Literal l ? l : null;
    }

    public Trigger withLiteral(Term newLiteral) {
        return new Trigger(op, type, newLiteral);
    }

    @Override
    public String toString() {
        return op.toString() + type + literal;
    }
}
