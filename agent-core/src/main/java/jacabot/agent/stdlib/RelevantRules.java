package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;

/**
 * {@code .relevant_rules(Pattern, Rules)}: the rules whose head unifies with Pattern (all of them
 * when Pattern is free), as terms, without sources, with their variables as written (as Jason's).
 */
final class RelevantRules extends DefaultInternalAction {
    RelevantRules() {
        super(".relevant_rules", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        boolean any = args[0] instanceof Var;
        Literal pattern = any ? null : literal(args[0]);
        var rules = new ArrayList<Term>();
        for (BeliefBase.Entry e : any ? ag.beliefBase().all() : ag.beliefBase().candidates(pattern)) {
            if (e.rule() != null && (any || un.copy().unifies(pattern, e.rule().head()))) {
                Literal head = e.rule().head().withoutSources();
                rules.add(Literal.of(Literal.RULE_TERM, head, e.rule().body()));
            }
        }
        return un.unifies(args[1], listOf(rules));
    }
}
