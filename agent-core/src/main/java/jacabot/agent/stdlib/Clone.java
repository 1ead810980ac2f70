package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.BeliefBase;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Term;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code .clone(Name)}: a new agent with this agent's current beliefs, rules and plans (not its
 * goals, events or intentions), as Jason's clone.
 */
final class Clone extends DefaultInternalAction {
    Clone() {
        super(".clone", 1, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        var beliefs = new ArrayList<Object>();
        for (BeliefBase.Entry e : ag.beliefBase().all()) {
            beliefs.add(e.rule() != null ? e.rule() : e.literal());
        }
        var program = new AgentProgram(ag.name(), beliefs, List.of(), new ArrayList<>(ag.planLibrary().plans()));
        String created;
        try {
            created = ag.arch().cloneAgent(text(args[0]), program, ag.parser());
        } catch (IllegalArgumentException e) {
            throw IaException.wrongArguments(name(), e.getMessage());
        }
        if (created == null) {
            throw IaException.wrongArguments(name(), "this infrastructure cannot create agents");
        }
        return true;
    }
}
