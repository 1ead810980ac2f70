package jacabot.agent.syntax;

/**
 * One method per kind of term. A new kind of term adds a method here, and the compiler then lists
 * every visitor that must handle it (JDK 17 has no pattern switch over the sealed {@link Term}).
 */
public interface TermVisitor<R> {
    R visitLiteral(Literal t);

    R visitNumber(NumberTerm t);

    R visitString(StringTerm t);

    R visitVar(Var t);

    R visitAnnotatedVar(AnnotatedVar t);

    R visitEmptyList(ListTerm.Empty t);

    R visitCons(ListTerm.Cons t);

    R visitArith(ArithExpr t);

    R visitRel(RelExpr t);

    R visitLog(LogExpr t);

    R visitFunction(ArithFunction t);

    R visitTrigger(TriggerTerm t);

    R visitBody(BodyTerm t);

    R visitPlan(PlanTerm t);

    R visitObject(ObjectTerm t);
}
