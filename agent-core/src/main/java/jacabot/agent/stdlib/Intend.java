package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code .intend(G)} and {@code .intend(G, Id)}: succeeds for each intention pursuing G
 * (backtracking), Id its number. As Jason's, an intention suspended by {@code .suspend} is not
 * intended (it is still desired); one waiting in {@code .wait} is.
 */
final class Intend extends DefaultInternalAction {
    Intend() {
        super(".intend", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var out = new ArrayList<Unifier>();
        addIntended(ag, args[0], args.length == 2 ? args[1] : null, un, false, out);
        return out.iterator();
    }

    /**
     * Adds a solution for every intended means pursuing goal g, with id (when given) unified with
     * its intention's number; suspended intentions only when asked (as {@code .desire} does).
     */
    static void addIntended(Agent ag, Term g, Term id, Unifier un, boolean withSuspended, List<Unifier> out) {
        for (Intention i : ag.circumstance().allIntentions()) {
            if (i.isSuspended() && !withSuspended) {
                continue;
            }
            for (IntendedMeans im : i) {
                Trigger t = im.trigger();
                Unifier c = un.copy();
                if (t.isAchieveGoal() && t.isAddition() && c.unifies(g, t.literal())
                        && (id == null || c.unifies(id, new NumberTerm(i.id())))) {
                    out.add(c);
                }
            }
        }
    }
}
