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

/**
 * {@code while (C) {B}}, as Jason's {@code .loop}: the condition is tested against the unifier the
 * loop started with, so variables bound in one iteration are free again in the next.
 */
final class Loop extends DefaultInternalAction {
    Loop() {
        super(".loop", 2, 3);
    }

    @Override
    public boolean appliesArguments() {
        return false;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        IntendedMeans im = ag.circumstance().selectedIntention().peek();
        BodyStep loopStep = im.currentStep();
        Unifier start = un;
        if (args.length == 2) {
            Literal withBackup = Literal.of(".loop", args[0], args[1], new ObjectTerm(un.copy()));
            loopStep = loopStep.withTerm(withBackup);
        } else {
            start = (Unifier) ((ObjectTerm) args[2]).value();
        }
        // the condition is proved in the loop's unifier, reset to the saved one: it then holds
        // the first solution, or is left as saved when there is none (no unifier of its own)
        un.setFrom(start);
        boolean holds;
        try {
            holds = ag.solver().believes(args[0], un);
        } catch (RuntimeException | StackOverflowError e) {
            un.setFrom(start); // a proof cut short leaves no bindings behind
            throw e;
        }
        if (holds) {
            im.insertAfterCurrent(((BodyTerm) args[1]).steps(), loopStep);
        }
        return true;
    }
}
