package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.GoalStates;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;

/**
 * {@code .done} / {@code .done(G)}: the current goal (or goal G) of this intention only is achieved;
 * as in Jason, a G this intention does not pursue ends the intention without any goal state.
 */
final class Done extends DefaultInternalAction {
    Done() {
        super(".done", 0, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Intention i = ag.circumstance().selectedIntention();
        if (i == null || i.peek() == null) {
            return true; // not run by an intention (e.g. a rule): nothing to end
        }
        Literal goal = args.length == 0 ? literal(i.peek().trigger().literal()) : literal(args[0]);
        IntendedMeans im = i.dropGoal(goal, ag.newUnifier());
        if (im == null) {
            while (!i.isFinished()) {
                i.pop();
            }
            return true;
        }
        ag.goalStates().finished(GoalStates.of(im), GoalStates.State.achieved);
        if (!i.isFinished()) {
            ag.clearIntention(i);
        }
        return true;
    }
}
