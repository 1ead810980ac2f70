package jacabot.agent.syntax;

import java.util.function.Consumer;

/** A number; AgentSpeak numbers are doubles, printed without a decimal point when integral. */
public record NumberTerm(double value) implements Term {
    public static final NumberTerm ZERO = new NumberTerm(0);

    public static NumberTerm of(double value) {
        return new NumberTerm(value);
    }

    @Override
    public boolean isGround() {
        return true;
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
    }

    @Override
    public boolean equals(Object o) {
        // Jason's: one NaN equals itself, the term, and no other
        return o == this || o instanceof NumberTerm n && n.value == value;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(value == 0 ? 0 : value);
    }

    @Override
    public String toString() {
        return format(value);
    }

    /** Jason's number format: {@code 3}, {@code 1.5}, {@code 1.0E20}. */
    public static String format(double value) {
        long r = Math.round(value);
        return value == (double) r ? Long.toString(r) : Double.toString(value);
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitNumber(this);
    }
}
