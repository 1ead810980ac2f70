package jacabot.agent.syntax;

import java.util.function.Consumer;

/**
 * An operator applied to one or two operands: arithmetic, relational and logical expressions.
 * A unary expression has no right operand.
 */
public sealed interface OperatorExpr extends Term permits ArithExpr, RelExpr, LogExpr {

    Term left();

    /** The right operand, or {@code null} for a unary expression. */
    Term right();

    @Override
    default boolean isGround() {
        return left().isGround() && (right() == null || right().isGround());
    }

    @Override
    default void collectVars(Consumer<Var> sink) {
        left().collectVars(sink);
        if (right() != null) {
            right().collectVars(sink);
        }
    }
}
