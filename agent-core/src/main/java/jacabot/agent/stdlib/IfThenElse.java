package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Term;

/** {@code if (C) {A} elif ... else {B}}, as Jason's {@code .if_then_else(C, {A}, {B})}. */
final class IfThenElse extends DefaultInternalAction {
    IfThenElse() {
        super(".if_then_else", 2, 3);
    }

    @Override
    public boolean appliesArguments() {
        return false;
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        BodyTerm branch = null;
        if (ag.solver().believes(args[0], un)) {
            branch = (BodyTerm) args[1];
        } else if (args.length == 3) {
            branch = (BodyTerm) args[2];
        }
        if (branch != null) {
            ag.circumstance().selectedIntention().peek().insertAfterCurrent(branch.steps());
        }
        return true;
    }
}
