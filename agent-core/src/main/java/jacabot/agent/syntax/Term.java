package jacabot.agent.syntax;

import java.util.function.Consumer;

/**
 * An AgentSpeak term. Terms are immutable values with structural equality; variables are
 * bound by a {@code Unifier}, never by changing a term.
 *
 * <p>Ordering follows Jason's standard order: numbers, then strings, then lists, then
 * literals (by functor, negation, arguments and annotations), then variables.
 */
public sealed interface Term extends Comparable<Term>
        permits Literal, NumberTerm, StringTerm, Var, AnnotatedVar, ListTerm, OperatorExpr, ArithFunction,
                TriggerTerm, BodyTerm, PlanTerm, ObjectTerm {

    /** {@return whether the term has no variable} */
    boolean isGround();

    /** {@return what the visitor makes of this kind of term} */
    <R> R accept(TermVisitor<R> v);

    /** Visits every variable of the term, in textual order. */
    void collectVars(Consumer<Var> sink);

    @Override
    default int compareTo(Term other) {
        return TermOrder.compare(this, other);
    }
}
