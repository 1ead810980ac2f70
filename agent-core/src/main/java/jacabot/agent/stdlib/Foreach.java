package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.IntendedMeans;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.semantics.Solver;

/**
 * {@code for (C) {B}}, as Jason's {@code .foreach}: the body runs once for each solution of C
 * (found lazily), and the unifier is restored after the loop.
 */
final class Foreach extends DefaultInternalAction {
    Foreach() {
        super(".foreach", 2, 4);
    }

    @Override
    public boolean appliesArguments() {
        return false;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        IntendedMeans im = ag.circumstance().selectedIntention().peek();
        BodyStep forStep = im.currentStep();
        Solver.Answers answers;
        Unifier backup;
        if (args.length == 2) {
            backup = un.copy();
            answers = ag.solver().solve(args[0], backup);
            // each solution is given into the loop's unifier, with no unifier of its own
            if (!answers.next(un)) {
                return true;
            }
            forStep = forStep.withTerm(Literal.of(".foreach", args[0], args[1], new ObjectTerm(answers), new ObjectTerm(backup)));
            im.insertAfterCurrent(((BodyTerm) args[1]).steps(), forStep);
            return true;
        }
        answers = (Solver.Answers) ((ObjectTerm) args[2]).value();
        backup = (Unifier) ((ObjectTerm) args[3]).value();
        if (answers.next(un)) {
            im.insertAfterCurrent(((BodyTerm) args[1]).steps(), forStep);
        } else {
            un.setFrom(backup);
        }
        return true;
    }
}
