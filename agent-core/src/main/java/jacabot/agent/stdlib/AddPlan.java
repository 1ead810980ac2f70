package jacabot.agent.stdlib;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.List;

/** {@code .add_plan(P[, Source[, begin|end]])}: adds a plan (a plan term, a string, or a list of them). */
final class AddPlan extends DefaultInternalAction {
    AddPlan() {
        super(".add_plan", 1, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean begin = args.length == 3 && args[2].toString().equals("begin");
        List<Term> items = args[0] instanceof ListTerm l ? l.elements() : List.of(args[0]);
        for (Term t : items) {
            Plan p;
            if (t instanceof PlanTerm pt) {
                try {
                    p = pt.toPlan();
                } catch (IllegalArgumentException e) {
                    throw IaException.wrongArguments(name(), e.getMessage());
                }
            } else if (t instanceof StringTerm s) {
                try {
                    p = ag.parser().parsePlan(s.value());
                } catch (AslSyntaxException e) {
                    throw IaException.wrongArguments(name(), e.getMessage());
                }
            } else {
                throw IaException.wrongArguments(name(), "The term '" + t + "' (" + jasonClass(t) + ") can not be used as a plan for .add_plan.");
            }
            ag.planLibrary().add(p, args.length >= 2 ? args[1] : Literal.SELF, begin);
        }
        return true;
    }

    /** The name of the class Jason 3.2.0 gives such a term, which its message names. */
    private static String jasonClass(Term t) {
        if (t instanceof NumberTerm) {
            return "NumberTermImpl";
        }
        if (t instanceof ListTerm) {
            return "ListTermImpl";
        }
        if (t instanceof Var || t instanceof AnnotatedVar) {
            return "VarTerm";
        }
        return t instanceof Literal l && l.isAtom() ? "Atom" : "LiteralImpl";
    }
}
