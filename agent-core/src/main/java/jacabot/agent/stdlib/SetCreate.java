package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;

/** {@code .set.create(S)}: S is a new empty set (fails when S is bound to something else, as Jason's). */
final class SetCreate extends DefaultInternalAction {
    SetCreate() {
        super(".set.create", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], new ObjectTerm(new TermCollections.TermSet()));
    }
}
