package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.time.LocalTime;

/** {@code .time(H, M, S[, MS])}: the time of day from the agent's clock (simulated time starts at 0:00). */
final class Time extends DefaultInternalAction {
    Time() {
        super(".time", 3, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        LocalTime t = ag.clock().timeOfDay();
        boolean ok = un.unifies(args[0], new NumberTerm(t.getHour())) && un.unifies(args[1], new NumberTerm(t.getMinute()))
                && un.unifies(args[2], new NumberTerm(t.getSecond()));
        return ok && (args.length < 4 || un.unifies(args[3], new NumberTerm(t.getNano() / 1_000_000)));
    }
}
