package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;

/**
 * {@code .list_rules}: prints the agent's rules, one a line, in the belief base's order;
 * arguments are ignored, as by Jason's. Jason also lists the {@code kqml::} rules of its KQML
 * support (handled natively here, so not rules to list), and its order of predicates is that of a
 * hash map.
 */
final class ListRules extends DefaultInternalAction {
    ListRules() {
        super(".list_rules", 0, Integer.MAX_VALUE);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        for (BeliefBase.Entry e : ag.beliefBase().all()) {
            if (e.rule() != null) {
                ag.print(e.rule().toString());
            }
        }
        return true;
    }
}
