package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.TriggerTerm;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code .list_plans}: prints the plan library as Jason does, in one console message: the plans
 * of each source file under {@code // plans from file:F}, then those from no file (told, added,
 * made by a directive). {@code .list_plans({+!g})} prints the plans relevant for a trigger, one
 * a line.
 */
final class ListPlans extends DefaultInternalAction {
    ListPlans() {
        super(".list_plans", 0, 1);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (args.length == 1) {
            if (!(args[0] instanceof TriggerTerm tt)) {
                throw IaException.wrongArguments(name(), "'" + args[0] + "' is not a trigger");
            }
            Term asked = RelevantPlans.withSelfSource(tt.trigger().literal(), ag);
            for (Plan p : ag.planLibrary().candidates(tt.trigger())) {
                if (ag.planLibrary().plans().contains(p) && ag.newUnifier().unifies(p.trigger().literal(), asked)) {
                    ag.print(p.toString());
                }
            }
            return true;
        }
        Map<String, List<Plan>> byFile = new LinkedHashMap<>();
        var noFile = new ArrayList<Plan>();
        for (Plan p : ag.planLibrary().plans()) {
            Literal url = p.label() == null ? null : p.label().getAnnot("url");
            if (url != null && url.arity() == 1 && url.arg(0) instanceof StringTerm file) {
                byFile.computeIfAbsent(file.value(), f -> new ArrayList<>()).add(p);
            } else {
                noFile.add(p);
            }
        }
        var out = new StringBuilder();
        for (Map.Entry<String, List<Plan>> e : byFile.entrySet()) {
            out.append("\n\n// plans from ").append(e.getKey()).append("\n\n");
            e.getValue().forEach(p -> out.append(p).append('\n'));
            out.append('\n');
        }
        if (!noFile.isEmpty()) {
            out.append("\n\n// plans without file\n\n");
            noFile.forEach(p -> out.append(p).append('\n'));
        }
        ag.print(out.toString());
        return true;
    }
}
