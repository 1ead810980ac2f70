package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code .belief(B)}: B unifies with a belief (its annotations a subset of the belief's), one
 * solution per belief in the belief base's order. Unlike a query, rules are not used: as Jason's,
 * only stored facts count.
 */
final class Belief extends DefaultInternalAction {
    Belief() {
        super(".belief", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Term b = args[0];
        List<BeliefBase.Entry> entries;
        if (b instanceof Var || b instanceof AnnotatedVar) {
            entries = ag.beliefBase().all();
        } else if (b instanceof Literal l) {
            entries = ag.beliefBase().candidates(l);
        } else {
            throw new IaException("unknown", "Wrong argument for internal action 'belief': '" + b + "' is not a literal");
        }
        var out = new ArrayList<Unifier>();
        for (BeliefBase.Entry e : entries) {
            if (e.rule() != null) {
                continue;
            }
            // a fact with variables: they are its own, apart from the query's
            Term fact = e.isGround() ? e.literal() : Renamer.renameApart(e.literal(), ag);
            Unifier c = un.copy();
            if (c.unifies(b, fact)) {
                out.add(c);
            }
        }
        return out.iterator();
    }
}
