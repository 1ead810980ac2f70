package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

import java.util.Collection;
import java.util.Locale;

/** {@code .set.union(S, C)}, {@code .set.intersection(S, C)}, {@code .set.difference(S, C)}: change S in place by a list, set or queue C. */
final class SetOperation extends DefaultInternalAction {
    enum Kind { UNION, INTERSECTION, DIFFERENCE }

    private final Kind kind;

    SetOperation(Kind kind) {
        super(".set." + kind.name().toLowerCase(Locale.ROOT), 2, 2);
        this.kind = kind;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var set = TermCollections.set(name(), args[0]);
        Collection<Term> items = TermCollections.elements(args[1]);
        if (items == null) {
            throw IaException.wrongArguments(name(), "'" + args[1] + "' is not a list or a set");
        }
        // membership by the standard order, as the set's own (a list's contains would use equals)
        var other = new TermCollections.TermSet(items);
        switch (kind) {
            case UNION -> set.addAll(other);
            case INTERSECTION -> set.retainAll(other);
            case DIFFERENCE -> set.removeAll(other);
        }
        return true;
    }
}
