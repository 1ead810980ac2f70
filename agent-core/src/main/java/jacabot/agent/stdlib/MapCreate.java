package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;

/** {@code .map.create(M)}: M is a new empty map (fails when M is bound to something else, as Jason's). */
final class MapCreate extends DefaultInternalAction {
    MapCreate() {
        super(".map.create", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        return un.unifies(args[0], new ObjectTerm(new TermCollections.TermMap()));
    }
}
