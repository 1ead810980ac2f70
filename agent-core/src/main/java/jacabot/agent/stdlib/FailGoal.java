package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.GoalDropper;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .fail_goal(G)}: makes goal G fail, triggering {@code -!G}. */
final class FailGoal extends DefaultInternalAction {
    FailGoal() {
        super(".fail_goal", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        new GoalDropper(ag, GoalDropper.Mode.FAIL, firstLiteral(args)).drop();
        return true;
    }
}
