package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Term;
import java.util.Arrays;
import java.util.Set;

/**
 * {@code .log(Level, a, ...)}: as {@code .print} at a logging level; Jason's console shows the
 * levels {@code info}, {@code warning} and {@code severe}, not {@code fine}, {@code finer}...
 */
final class Log extends DefaultInternalAction {
    private static final Set<String> SHOWN = Set.of("info", "warning", "severe");

    Log() {
        super(".log", 1, Integer.MAX_VALUE);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (SHOWN.contains(text(args[0]))) {
            Print.printConcatenated(ag, Arrays.copyOfRange(args, 1, args.length));
        }
        return true;
    }
}
