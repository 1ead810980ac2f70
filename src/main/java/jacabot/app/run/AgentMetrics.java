package jacabot.app.run;
import jacabot.robot.Experiment;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Term;
import java.util.Set;
import java.util.TreeSet;

/**
 * The agent's side of the Chapter 5 comparison: how much code, how many plans, how many
 * conditions (the atomic formulas of plan contexts, the counterpart of the baselines' tests) and
 * which coordination beliefs (beliefs the agent adds and removes itself to order its tasks).
 */
public record AgentMetrics(Experiment experiment, int codeLines, int plans, int contexts, int conditions,
        Set<String> coordinationBeliefs) {

    /** {@return the figures of an agent given as text (it includes files only by their path)} */
    public static AgentMetrics of(Experiment e, String source) throws AslSyntaxException {
        return of(e, AgentSource.text(e.id() + ".asl", source));
    }

    /** {@return the figures of an agent and the sources it includes (the code lines of each count)} */
    public static AgentMetrics of(Experiment e, AgentSource agent) throws AslSyntaxException {
        AgentProgram program = agent.parse(agent.parser());
        int code = 0;
        for (var source : agent.sources()) {
            for (String line : source.text().split("\n")) {
                String t = line.trim();
                if (!t.isEmpty() && !t.startsWith("//") && !t.startsWith("/*") && !t.startsWith("*")) {
                    code++;
                }
            }
        }
        int contexts = 0;
        int conditions = 0;
        var beliefs = new TreeSet<String>();
        for (Plan p : program.plans()) {
            if (p.context() != null) {
                contexts++;
                conditions += atoms(p.context());
            }
            collectBeliefs(p.body(), beliefs);
        }
        return new AgentMetrics(e, code, program.plans().size(), contexts, conditions, beliefs);
    }

    private static int atoms(Term t) {
        if (t instanceof LogExpr e) {
            return atoms(e.left()) + (e.right() == null ? 0 : atoms(e.right()));
        }
        return t instanceof Literal || t instanceof RelExpr ? 1 : 0;
    }

    private static void collectBeliefs(BodyTerm body, Set<String> out) {
        for (BodyStep s : body.steps()) {
            switch (s.kind()) {
                case ADD_BEL:
                case ADD_BEL_END:
                case ADD_BEL_NEW_FOCUS:
                case DEL_BEL:
                case DEL_BEL_NEW_FOCUS:
                case DEL_ADD_BEL:
                    if (s.term() instanceof Literal l) {
                        out.add((l.negated() ? "~" : "") + l.functor());
                    }
                    break;
                default:
                    if (s.term() instanceof Literal l) {
                        for (Term a : l.args()) {
                            if (a instanceof BodyTerm b) {
                                collectBeliefs(b, out);
                            }
                        }
                    }
            }
        }
    }
}
