package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;

/**
 * {@code .relevant_plan({+!g}, P)}: P is each plan relevant for the trigger in turn, as Jason's:
 * the library's plan itself, its variables not renamed, the trigger unified with the plan's in
 * the caller's unifier (so the two share variables), printed as a plan and not in braces.
 * {@code .relevant_plan(T, P)} with a plan P and a free T gives P's trigger.
 */
final class RelevantPlan extends DefaultInternalAction {
    RelevantPlan() {
        super(".relevant_plan", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args[0] instanceof Var && args[1] instanceof PlanTerm p) {
            return un.unifies(args[0], new TriggerTerm(p.trigger(), true));
        }
        if (!(args[0] instanceof TriggerTerm tt)) {
            throw IaException.wrongArguments(name(), "first argument '" + args[0] + "' must follow the syntax of a trigger.");
        }
        Term asked = RelevantPlans.withSelfSource(tt.trigger().literal(), ag);
        var solutions = new ArrayList<Unifier>();
        for (Plan p : ag.planLibrary().candidates(tt.trigger())) {
            Unifier u = un.copy();
            // the caller's variables are bound to the plan's (which print as written, as Jason's),
            // then the plan's annotations are matched against the asked trigger's
            if (!ag.planLibrary().isKqmlPlan(p) && u.unifies(withoutAnnots(asked), withoutAnnots(p.trigger().literal()))
                    && u.unifies(p.trigger().literal(), asked) && u.unifies(args[1], new PlanTerm(p).printedBare(true))) {
                solutions.add(u);
            }
        }
        return solutions.iterator();
    }

    private static Term withoutAnnots(Term t) {
        return t instanceof Literal l ? l.withoutAnnots() : t;
    }
}
