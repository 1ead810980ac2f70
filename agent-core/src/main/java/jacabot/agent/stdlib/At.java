package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.TriggerTerm;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** {@code .at("now +3 s", {+!g})}: posts the event when the agent's clock reaches that time. */
final class At extends DefaultInternalAction {
    private static final Pattern WHEN = Pattern.compile("\\s*now\\s*\\+\\s*(\\d+(?:\\.\\d+)?)\\s*([a-z]*)\\s*");

    At() {
        super(".at", 2, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        Matcher m = WHEN.matcher(text(args[0]));
        if (!m.matches()) {
            throw IaException.wrongArguments(name(), "'" + args[0] + "' is not a time as \"now +N unit\"");
        }
        double n = Double.parseDouble(m.group(1));
        long ms;
        switch (m.group(2)) {
            case "": case "ms": case "milliseconds": ms = (long) n; break;
            case "s": case "second": case "seconds": ms = (long) (n * 1000); break;
            case "m": case "min": case "minute": case "minutes": ms = (long) (n * 60_000); break;
            case "h": case "hour": case "hours": ms = (long) (n * 3_600_000); break;
            case "d": case "day": case "days": ms = (long) (n * 86_400_000); break;
            default: throw IaException.wrongArguments(name(), "unknown time unit '" + m.group(2) + "'");
        }
        if (!(args[1] instanceof TriggerTerm tt) || !(tt.trigger().literal() instanceof Literal l)) {
            throw IaException.wrongArguments(name(), "'" + args[1] + "' is not an event");
        }
        Trigger event = tt.trigger().withLiteral(l.hasSource() ? l : l.addAnnot(Literal.SOURCE_SELF));
        ag.schedule(ag.clock().millis() + ms, () -> ag.addExternalEvent(event));
        return true;
    }
}
