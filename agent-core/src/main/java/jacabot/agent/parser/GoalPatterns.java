package jacabot.agent.parser;

import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/**
 * Jason's goal patterns, the directives {@code { begin P } plans { end }} that turn the plans for
 * a goal into a declarative goal (the DALT 2006 patterns, as Jason 3.2 writes them):
 * <ul>
 * <li>{@code dg(G)}: {@code +!G : G.} and {@code +!G : .intend(G).} first, the block's plans for
 *     G ending with {@code ?G}, then {@code +G <- .succeed_goal(G).}</li>
 * <li>{@code bdg(G)}: dg, and {@code -!G <- !G.} (backtracking)</li>
 * <li>{@code bc(G[, P])}: P (bdg by default), and {@code +!G <- !G.} (blind commitment)</li>
 * <li>{@code smc(G, F)}: bc, and {@code +F <- .fail_goal(G).} (single-minded commitment)</li>
 * </ul>
 * The generated plans have no source file. A plan is for G when its trigger has G's functor and
 * arity (Jason unifies them).
 */
final class GoalPatterns {
    private GoalPatterns() {
    }

    /** {@return the plans of a block under pattern {@code p}, or null when p is not a goal pattern} */
    static List<Plan> apply(Literal p, List<Plan> inner, AslParser parser) throws AslSyntaxException {
        switch (p.functor()) {
            case "dg":
                return p.arity() == 1 ? dg(p.arg(0), inner, parser) : null;
            case "bdg":
                return p.arity() == 1 ? bdg(p.arg(0), inner, parser) : null;
            case "bc":
                if (p.arity() == 1) {
                    return with(bdg(p.arg(0), inner, parser), parser, "+!" + p.arg(0) + " <- !" + p.arg(0) + ".");
                }
                if (p.arity() == 2 && p.arg(1) instanceof Literal sub) {
                    List<Plan> base = apply(sub, inner, parser);
                    return base == null ? null : with(base, parser, "+!" + p.arg(0) + " <- !" + p.arg(0) + ".");
                }
                return null;
            case "smc":
                if (p.arity() != 2) {
                    return null;
                }
                List<Plan> bc = apply(Literal.of("bc", p.arg(0)), inner, parser);
                return with(bc, parser, "+" + p.arg(1) + " <- .fail_goal(" + p.arg(0) + ").");
            default:
                return null;
        }
    }

    private static List<Plan> dg(Term goal, List<Plan> inner, AslParser parser) throws AslSyntaxException {
        var out = new ArrayList<Plan>();
        out.add(generated(parser, "+!" + goal + " : " + goal + "."));
        out.add(generated(parser, "+!" + goal + " : .intend(" + goal + ")."));
        for (Plan p : inner) {
            if (p.trigger().isAchieveGoal() && p.trigger().isAddition() && goal instanceof Literal g
                    && p.trigger().literal() instanceof Literal planGoal && planGoal.samePredicate(g)) {
                // the goal is achieved when believed: test it at the end of the plan
                var steps = new ArrayList<BodyStep>(p.body().steps());
                steps.add(new BodyStep(BodyStep.Kind.TEST, planGoal, p.source()));
                p = new Plan(p.label(), p.trigger(), p.context(), new BodyTerm(steps), p.source(), p.goalCondition());
            }
            out.add(p);
        }
        out.add(generated(parser, "+" + goal + " <- .succeed_goal(" + goal + ")."));
        return out;
    }

    private static List<Plan> bdg(Term goal, List<Plan> inner, AslParser parser) throws AslSyntaxException {
        return with(dg(goal, inner, parser), parser, "-!" + goal + " <- !" + goal + ".");
    }

    private static List<Plan> with(List<Plan> plans, AslParser parser, String more) throws AslSyntaxException {
        if (plans == null) {
            return null;
        }
        var out = new ArrayList<Plan>(plans);
        out.add(generated(parser, more));
        return out;
    }

    /** A plan of the pattern's own: it comes from no file. */
    private static Plan generated(AslParser parser, String text) throws AslSyntaxException {
        Plan p = parser.parsePlan(text);
        return new Plan(p.label(), p.trigger(), p.context(), p.body(), null);
    }
}
