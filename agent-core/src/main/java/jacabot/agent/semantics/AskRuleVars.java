package jacabot.agent.semantics;

import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The fresh variables ({@code _N}) Jason 3.2 takes when it answers an ask with its default plans,
 * which we answer in Java ({@link MessageHandler}). Jason's plans ask the rule
 * {@code kqml::bel_no_source_self(NS, Content, Ans)}, which walks the belief's annotations with the
 * recursive rule {@code kqml::clear_source_self}; each query of a rule renames the query's free
 * variables apart, one fresh number each. We take the same numbers, so the {@code _N} an agent prints
 * after an ask are Jason's. Counts recorded from Jason 3.2.0 (one JVM, two agents asking each
 * other): askOne of a ground belief with one annotation it does not name takes 2; askAll of two such beliefs with one
 * variable in the content takes 6; an askOne nobody can answer takes one more per variable of its
 * content, then two per variable.
 */
final class AskRuleVars {
    private final Agent ag;

    AskRuleVars(Agent ag) {
        this.ag = ag;
    }

    /** The query {@code bel_no_source_self(NS, Content, Ans)}: the content's free variables and {@code Ans}. */
    void ruleQuery(Term content) {
        take(freeVars(content) + 1);
    }

    /**
     * One solution, {@code asked} as it matched {@code belief} in the belief base:
     * {@code clear_source_self} is asked once for each annotation of the belief the content did
     * not name; an askAll, which looks for every solution, also asks it for the empty rest.
     */
    void solution(Literal asked, Literal belief, boolean everySolution) {
        int rest = belief == null ? 0 : Math.max(0, belief.annots().size() - asked.annots().size());
        take(rest + (everySolution ? 1 : 0));
    }

    /** An askOne neither a belief nor a {@code +?} plan answers: the test goal and its failure rename the content twice. */
    void unanswered(Term content) {
        take(2 * freeVars(content));
    }

    private static int freeVars(Term content) {
        Set<Var> vars = new LinkedHashSet<>();
        content.collectVars(vars::add);
        return vars.size();
    }

    private void take(int n) {
        for (int i = 0; i < n; i++) {
            ag.freshVar(ANONYMOUS);
        }
    }

    private static final Var ANONYMOUS = new Var("_");
}
