package jacabot.agent.syntax;

import java.util.List;
import java.util.function.Consumer;

/** A call of an arithmetic function such as {@code math.sqrt(X)} or {@code .count(b(_))}. */
public record ArithFunction(String name, List<Term> args) implements Term {
    public ArithFunction {
        args = List.copyOf(args);
    }

    @Override
    public boolean isGround() {
        return args.stream().allMatch(Term::isGround);
    }

    @Override
    public void collectVars(Consumer<Var> sink) {
        args.forEach(a -> a.collectVars(sink));
    }

    @Override
    public String toString() {
        var sb = new StringBuilder(name).append('(');
        TermOrder.join(sb, args);
        return sb.append(')').toString();
    }

    @Override
    public <R> R accept(TermVisitor<R> v) {
        return v.visitFunction(this);
    }
}
