package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayList;
import java.util.List;

/** {@code .intend(G)}: succeeds for each intention pursuing G (backtracking). */
final class Intend extends DefaultInternalAction {
    Intend() {
        super(".intend", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new ArrayList<Unifier>();
        addIntended(ag, args[0], un, out);
        return out.iterator();
    }

    /** Adds a solution for every intended means pursuing goal g. */
    static void addIntended(Agent ag, Term g, Unifier un, List<Unifier> out) {
        for (Intention i : ag.circumstance().allIntentions()) {
            for (IntendedMeans im : i) {
                Trigger t = im.trigger();
                Unifier c = un.copy();
                if (t.isAchieveGoal() && t.isAddition() && c.unifies(g, t.literal())) {
                    out.add(c);
                }
            }
        }
    }
}
