package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/** {@code .print(a, ...)}: prints the arguments concatenated, strings without quotes. */
final class Print extends DefaultInternalAction {
    Print() {
        super(".print", 0, 2147483647);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return printConcatenated(ag, args);
    }

    static boolean printConcatenated(Agent ag, Term[] args) {
        var sb = new StringBuilder();
        for (Term t : args) {
            sb.append(text(t));
            if (t instanceof Var || t instanceof AnnotatedVar) {
                sb.append("<no-value>"); // as Jason prints a variable still free
            }
        }
        ag.print(sb.toString());
        return true;
    }
}
