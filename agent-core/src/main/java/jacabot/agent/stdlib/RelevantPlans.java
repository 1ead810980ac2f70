package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;

/** {@code .relevant_plans({+!g}, Plans[, Labels])}: the plans relevant for a trigger, in order. */
final class RelevantPlans extends DefaultInternalAction {
    RelevantPlans() {
        super(".relevant_plans", 2, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof TriggerTerm tt)) {
            throw IaException.wrongArguments(name(), "'" + args[0] + "' is not a trigger");
        }
        var plans = new ArrayList<Term>();
        var labels = new ArrayList<Term>();
        Term asked = RelevantPlans.withSelfSource(tt.trigger().literal(), ag);
        for (Plan p : ag.planLibrary().candidates(tt.trigger())) {
            if (!ag.planLibrary().isKqmlPlan(p) && ag.newUnifier().unifies(p.trigger().literal(), asked)) {
                plans.add(Renamer.renameApart(new PlanTerm(p), ag)); // its variables are its own
                labels.add(p.label());
            }
        }
        return un.unifies(args[1], listOf(plans)) && (args.length < 3 || un.unifies(args[2], listOf(labels)));
    }

    /** A trigger without a source is asked for as the agent's own ({@code source(self)}), as Jason's. */
    static Term withSelfSource(Term t, Agent ag) {
        if (t instanceof Literal l && !l.hasSource()) {
            ag.freshVar(ANONYMOUS); // Jason asks with source(_), a fresh variable: its number is taken
            return l.addAnnot(Literal.SOURCE_SELF);
        }
        return t;
    }

    private static final Var ANONYMOUS = new Var("_");
}
