package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;

/** {@code .substring(Sub, S[, Pos])} finds Sub in S (each position); with S unbound, {@code .substring(S0, S, Start[, End])} extracts. */
final class Substring extends DefaultInternalAction {
    Substring() {
        super(".substring", 2, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String whole = text(args[0]);
        if (args.length >= 3 && args[1] instanceof jacabot.agent.syntax.Var) {
            int start = (int) number(args[2]);
            int end = args.length == 4 ? (int) number(args[3]) : whole.length();
            if (start < 0 || end > whole.length() || start > end) {
                throw IaException.wrongArguments(name(), "bad bounds " + start + ", " + end);
            }
            return un.unifies(args[1], new StringTerm(whole.substring(start, end)));
        }
        String sub = whole;
        String in = text(args[1]);
        var out = new java.util.ArrayList<Unifier>();
        int from = 0;
        while (true) {
            int p = in.indexOf(sub, from);
            if (p < 0) {
                break;
            }
            Unifier c = un.copy();
            if (args.length < 3 || c.unifies(args[2], new NumberTerm(p))) {
                out.add(c);
            }
            from = p + 1;
            if (args.length < 3) {
                break;
            }
        }
        return out.iterator();
    }
}
