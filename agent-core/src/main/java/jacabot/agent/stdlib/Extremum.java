package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Collections;
import java.util.List;
import java.util.function.Function;

/** {@code .max(L, X)} and {@code .min(L, X)}: the greatest or least element in the standard order. */
final class Extremum extends DefaultInternalAction {
    private final Function<List<Term>, Term> pick;

    private Extremum(String name, Function<List<Term>, Term> pick) {
        super(name, 2, 2);
        this.pick = pick;
    }

    static Extremum max() {
        return new Extremum(".max", Collections::max);
    }

    static Extremum min() {
        return new Extremum(".min", Collections::min);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        checkFirstIsList(args);
        List<Term> items = list(args[0]).elements();
        if (items.isEmpty()) {
            return false;
        }
        return un.unifies(args[1], pick.apply(items));
    }
}
