package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Renamer;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;

/** {@code .relevant_rules(Pattern, Rules)}: the rules whose head unifies with Pattern, as terms, without sources. */
final class RelevantRules extends DefaultInternalAction {
    RelevantRules() {
        super(".relevant_rules", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Literal pattern = literal(args[0]);
        var rules = new ArrayList<Term>();
        for (BeliefBase.Entry e : ag.beliefBase().candidates(pattern)) {
            if (e.rule() != null && un.copy().unifies(pattern, e.rule().head())) {
                Literal head = e.rule().head().withoutSources();
                rules.add(Renamer.renameApart(Literal.of(Literal.RULE_TERM, head, e.rule().body()), ag));
            }
        }
        return un.unifies(args[1], listOf(rules));
    }
}
