package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Intention;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.ObjectTerm;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * {@code .fork(and|or, {B1}, {B2}, ...)}, what the body operators {@code B1 |&| B2} and
 * {@code B1 ||| B2} stand for: each branch runs in a copy of the intention, followed by
 * {@code .join}; with {@code and} the branch that joins last goes on with the rest of the plan,
 * with {@code or} the first one does and the other branches are dropped. The forking intention
 * itself ends here (as Jason's).
 */
final class Fork extends DefaultInternalAction {
    Fork() {
        super(".fork", 2, Integer.MAX_VALUE);
    }

    @Override
    public boolean suspendsIntention() {
        return true;
    }

    /** The branches of one fork and how many have still to join. */
    static final class Branches {
        final boolean and;
        final Set<Intention> running = new LinkedHashSet<>();
        int toJoin;

        Branches(boolean and) {
            this.and = and;
        }

        @Override
        public String toString() {
            return "fork(" + (and ? "and" : "or") + ")";
        }
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String kind = args[0].toString();
        if (!kind.equals("and") && !kind.equals("or")) {
            throw IaException.wrongArguments(name(), "the first argument must be 'and' or 'or'");
        }
        Branches b = new Branches(kind.equals("and"));
        Intention si = ag.circumstance().selectedIntention();
        BodyStep join = new BodyStep(BodyStep.Kind.INTERNAL_ACTION, Literal.of(".join", new ObjectTerm(b)),
                si.peek().currentStep().source());
        var copies = new ArrayList<Intention>();
        for (int k = 1; k < args.length; k++) {
            if (!(args[k] instanceof BodyTerm body)) {
                throw IaException.wrongArguments(name(), "'" + args[k] + "' is not a plan body");
            }
            Intention branch = ag.copyIntention(si);
            var steps = new ArrayList<BodyStep>(body.steps());
            steps.add(join);
            branch.peek().replaceCurrentStep(steps);
            copies.add(branch);
        }
        b.running.addAll(copies);
        b.toJoin = copies.size();
        ag.holdSelectedIntention();
        for (Intention branch : copies) {
            ag.circumstance().addRunningIntention(branch);
        }
        return true;
    }
}
