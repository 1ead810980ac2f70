package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Term;
import java.time.LocalDate;

/** {@code .date(Y, M, D)}: today's year, month (1 to 12) and day, in the machine's time zone. */
final class DateIa extends DefaultInternalAction {
    DateIa() {
        super(".date", 3, 3);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        LocalDate d = LocalDate.now();
        return un.unifies(args[0], new NumberTerm(d.getYear()))
                && un.unifies(args[1], new NumberTerm(d.getMonthValue()))
                && un.unifies(args[2], new NumberTerm(d.getDayOfMonth()));
    }
}
