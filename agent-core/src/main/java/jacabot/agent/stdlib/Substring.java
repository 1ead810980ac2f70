package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;

/**
 * {@code .substring(Sub, S[, Pos[, End]])} as Jason: with two arguments whether Sub occurs in S;
 * with an unbound Sub (or, kept by Jason for old programs, an unbound S) and a number Pos, the
 * text from Pos (to End); otherwise each position of Sub in S, one solution each. Terms that
 * are not strings are taken as their printed text.
 */
final class Substring extends DefaultInternalAction {
    Substring() {
        super(".substring", 2, 4);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        String sub = textOf(args[0]);
        String in = textOf(args[1]);
        if (args.length == 2) {
            return in.contains(sub);
        }
        boolean fixedStart = args[2] instanceof NumberTerm;
        if (fixedStart && (args[0] instanceof Var || args[1] instanceof Var)) {
            Term target = args[0] instanceof Var ? args[0] : args[1];
            String from = args[0] instanceof Var ? in : sub;
            int start = (int) number(args[2]);
            int end = args.length == 4 && args[3] instanceof NumberTerm ? (int) number(args[3]) : from.length();
            if (start < 0 || end > from.length() || start > end) {
                throw IaException.wrongArguments(name(), "bad bounds " + start + ", " + end);
            }
            return un.unifies(target, new StringTerm(from.substring(start, end)));
        }
        var out = new ArrayList<Unifier>();
        for (int p = in.indexOf(sub); p >= 0 && p < in.length(); p = in.indexOf(sub, p + 1)) {
            Unifier c = un.copy();
            // Jason's End is one less than the end of the match; kept for the same answers
            if (c.unifies(args[2], new NumberTerm(p)) && (args.length < 4 || c.unifies(args[3], new NumberTerm(p + sub.length() - 1)))) {
                out.add(c);
            }
        }
        return out.iterator();
    }

    private static String textOf(Term t) {
        return t instanceof StringTerm s ? s.value() : t.toString();
    }
}
