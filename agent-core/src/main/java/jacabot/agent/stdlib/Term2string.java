package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/** {@code .term2string(T, S)}: S is T as a string, or T is S parsed. */
final class Term2string extends DefaultInternalAction {
    Term2string() {
        super(".term2string", 2, 2);
    }

    /** Jason's three cases: compare, print, or parse (what does not parse is an atom of that text). */
    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean free = args[0] instanceof Var || args[0] instanceof AnnotatedVar;
        if (!free && args[1] instanceof StringTerm s) {
            return args[0].toString().equals(s.value());
        }
        if (!free && (args[1] instanceof Var || args[1] instanceof AnnotatedVar)) {
            return un.unifies(args[1], new StringTerm(args[0].toString()));
        }
        if (!free) {
            throw new IaException("internal_action", "invalid case of term2string");
        }
        String text = args[1] instanceof StringTerm s ? s.value() : args[1].toString();
        try {
            return un.unifies(args[0], ag.parser().parseTerm(text));
        } catch (AslSyntaxException e) {
            return un.unifies(args[0], Literal.atom(text));
        }
    }
}
