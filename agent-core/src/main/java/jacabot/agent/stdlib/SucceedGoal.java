package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.GoalDropper;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/** {@code .succeed_goal(G)}: ends goal G as if achieved, wherever it is pursued. */
final class SucceedGoal extends DefaultInternalAction {
    SucceedGoal() {
        super(".succeed_goal", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        new GoalDropper(ag, GoalDropper.Mode.SUCCEED, firstLiteral(args)).drop();
        return true;
    }
}
