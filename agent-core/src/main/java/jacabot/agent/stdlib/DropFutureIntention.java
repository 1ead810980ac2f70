package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/**
 * {@code .drop_future_intention(G)}: as Jason's, drops (without failure plans or goal states) every
 * intention whose top plan's body, as written and from its first step, has a step {@code !G} or
 * {@code !!G} unifying with G, the calling intention included; then drops the events for G, as
 * {@code .drop_desire}.
 */
final class DropFutureIntention extends DefaultInternalAction {
    DropFutureIntention() {
        super(".drop_future_intention", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Literal g = literal(args[0]);
        for (Intention i : ag.circumstance().allIntentions()) {
            IntendedMeans top = i.peek();
            if (top != null && postsGoal(top, g, un)) {
                ag.dropIntention(i);
            }
        }
        DropEvent.dropEvents(ag, g);
        return true;
    }

    /** Jason looks at the plan's steps as written, the unifier of the call being the only one. */
    private static boolean postsGoal(IntendedMeans im, Literal g, Unifier un) {
        for (BodyStep s : im.plan().body().steps()) {
            if ((s.kind() == BodyStep.Kind.ACHIEVE || s.kind() == BodyStep.Kind.ACHIEVE_NEW_FOCUS)
                    && un.copy().unifies(s.term(), g)) {
                return true;
            }
        }
        return false;
    }
}
