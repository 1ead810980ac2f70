package jacabot.agent.stdlib;

import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.IaException;
import jacabot.agent.semantics.Unifier;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code .puts(S[, R])} as Jason's: S with each {@code #{Name}} replaced by the value of the
 * variable (or the atom, or number) Name; an unbound variable gives its name ({@code #{_}} a new
 * unnamed variable, {@code _N}, as Jason reads it), and anything but
 * a bare name inside the braces is left as written. With a variable R the text is bound to R
 * instead of printed; with any other R, Jason prints S followed by R (interpolated too) only when
 * R is a string.
 */
final class Puts extends DefaultInternalAction {
    /** A name of letters, digits and {@code _} only: {@code #{ A }} or {@code #{1+2}} stay as they are. */
    private static final Pattern HOLE = Pattern.compile("#\\{(\\w+)\\}");

    Puts() {
        super(".puts", 1, 2);
    }

    @Override
    public Object execute(Agent ag, Unifier un, Term[] args) throws IaException {
        if (!(args[0] instanceof StringTerm s)) {
            throw new IaException("wrong_arguments", "Wrong argument for internal action 'puts': first argument must be a string");
        }
        String out = interpolate(s.value(), un, ag);
        if (args.length == 2) {
            if (args[1] instanceof Var || args[1] instanceof AnnotatedVar) {
                return un.unifies(args[1], new StringTerm(out));
            }
            if (args[1] instanceof StringTerm more) {
                out += interpolate(more.value(), un, ag);
            }
        }
        ag.print(out);
        return true;
    }

    private static String interpolate(String s, Unifier un, Agent ag) {
        Matcher m = HOLE.matcher(s);
        var sb = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(sb, Matcher.quoteReplacement(text(un.apply(named(m.group(1), ag)))));
        }
        m.appendTail(sb);
        return sb.toString();
    }

    /** The term a bare name stands for: a variable, a number or an atom. */
    private static Term named(String name, Agent ag) {
        if (name.equals("_")) {
            return ag.freshVar(new Var("_")); // read as Jason reads it: a new unnamed variable, _N
        }
        char c = name.charAt(0);
        if (Character.isUpperCase(c) || c == '_') {
            return new Var(name);
        }
        if (Character.isDigit(c)) {
            try {
                return new NumberTerm(Double.parseDouble(name));
            } catch (NumberFormatException e) {
                return Literal.atom(name); // such as 1a: Jason's parser would not read it as a number either
            }
        }
        return Literal.atom(name);
    }
}
