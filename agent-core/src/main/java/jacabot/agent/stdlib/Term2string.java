package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;

/** {@code .term2string(T, S)}: S is T as a string, or T is S parsed. */
final class Term2string extends DefaultInternalAction {
    Term2string() {
        super(".term2string", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean free = args[0] instanceof Var || args[0] instanceof AnnotatedVar;
        if (!free || !(args[1] instanceof StringTerm)) {
            return un.unifies(args[1], new StringTerm(args[0].toString()));
        }
        try {
            return un.unifies(args[0], ag.parser().parseTerm(((StringTerm) args[1]).value()));
        } catch (AslSyntaxException e) {
            throw IaException.wrongArguments(name(), "cannot parse '" + ((StringTerm) args[1]).value() + "'");
        }
    }
}
