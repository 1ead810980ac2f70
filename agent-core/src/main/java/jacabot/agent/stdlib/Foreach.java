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
import java.util.Iterator;

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
    @SuppressWarnings("unchecked")
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        IntendedMeans im = ag.circumstance().selectedIntention().peek();
        BodyStep forStep = im.currentStep();
        Iterator<Unifier> it;
        Unifier backup;
        if (args.length == 2) {
            it = ag.solver().solve(args[0], un.copy());
            if (!it.hasNext()) {
                return true;
            }
            backup = un.copy();
            forStep = forStep.withTerm(Literal.of(".foreach", args[0], args[1], new ObjectTerm(it), new ObjectTerm(backup)));
        } else {
            it = (Iterator<Unifier>) ((ObjectTerm) args[2]).value();
            backup = (Unifier) ((ObjectTerm) args[3]).value();
        }
        if (it.hasNext()) {
            un.setFrom(it.next());
            im.insertAfterCurrent(((BodyTerm) args[1]).steps(), forStep);
        } else {
            un.setFrom(backup);
        }
        return true;
    }
}
