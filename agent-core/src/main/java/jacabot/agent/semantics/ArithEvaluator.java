package jacabot.agent.semantics;

import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/** Jason's arithmetic functions: {@code math.*}, {@code .count} and {@code .length}. */
final class ArithEvaluator implements Unifier.Evaluator {
    private final Agent agent;

    /** Functions defined by rules ({@code register_function}), by {@code name/arity}. */
    private final Map<String, AgentProgram.UserFunction> userFunctions =
            new ConcurrentHashMap<>();

    /** system.time minus the agent's clock, fixed when system.time is first asked for. */
    private volatile long epochOffset = Long.MIN_VALUE;

    ArithEvaluator(Agent agent) {
        this.agent = agent;
    }

    private Unifier newUnifier() {
        var u = new Unifier();
        u.setEvaluator(this);
        return u;
    }

    void register(AgentProgram.UserFunction f) {
        userFunctions.put(f.name() + "/" + f.arity(), f);
    }

    /** A rule-defined function: the last argument of the first solution of {@code p(Args..., R)}. */
    private Term userFunction(AgentProgram.UserFunction f, List<Term> args, Unifier u) {
        var all = new ArrayList<Term>();
        for (Term a : args) {
            Term v = u.apply(a);
            if (!v.isGround()) {
                return null; // evaluated once its arguments are bound (e.g. inside .findall)
            }
            all.add(v);
        }
        var result = new Var("FunctionResult__");
        all.add(result);
        // a proof of its own: the caller may be inside a proof whose bindings must stay as they are
        Iterator<Unifier> it = agent.solver().solve(Literal.of(f.predicate(), all), newUnifier());
        if (!it.hasNext()) {
            return null;
        }
        Term value = it.next().apply(result);
        return value.isGround() ? value : null;
    }

    /** Jason's warning, on the console as its {@code ArithExpr} logger prints it. */
    @Override
    public void notANumber(ArithExpr e, Unifier u) {
        agent.solver().sideEffect();
        agent.arch().console("[ArithExpr] The value of " + e + " is not a number! Unifier = " + JasonHashOrder.text(u)
                + ". Code: " + e.src().jasonPosition());
    }

    @Override
    public Term evaluate(ArithFunction f, Unifier u) {
        List<Term> a = f.args();
        var user = userFunctions.isEmpty() ? null : userFunctions.get(f.name() + "/" + a.size());
        if (user != null) {
            agent.solver().sideEffect();
            return userFunction(user, a, u);
        }
        if (!f.name().equals(".count") && !a.stream().allMatch(Term::isGround)) {
            return null; // Jason evaluates a function over ground arguments only (but .count), else it stays as written
        }
        switch (f.name()) {
            case "system.time":
                agent.solver().sideEffect();
                // Jason's: ms since 1970; counted on the agent's clock from the computer's time when
                // first asked, so that it agrees with .wait (.system_time is the clock alone)
                if (epochOffset == Long.MIN_VALUE) {
                    epochOffset = System.currentTimeMillis() - agent.clock().millis();
                }
                return new NumberTerm(epochOffset + agent.clock().millis());
            case ".count": {
                int n = 0;
                Iterator<Unifier> it = agent.solver().solve(a.get(0), u);
                while (it.hasNext()) {
                    it.next();
                    n++;
                }
                return new NumberTerm(n);
            }
            case ".length":
                if (a.get(0) instanceof ListTerm l) {
                    return new NumberTerm(l.elements().size());
                }
                if (a.get(0) instanceof StringTerm s) {
                    return new NumberTerm(s.value().length());
                }
                return null;
            case "math.sum":
            case "math.average":
            case "math.mean":
            case "math.median":
            case "math.std_dev":
                return listFunction(f.name(), a.get(0));
            case "math.max":
            case "math.min":
                if (a.size() == 1) {
                    return extremeOf(f.name().equals("math.max"), a.get(0));
                }
                break;
            case "math.pi":
                return new NumberTerm(Math.PI);
            case "math.e":
                return new NumberTerm(Math.E);
            case "math.random":
                agent.solver().sideEffect();
                return new NumberTerm(a.isEmpty() ? agent.random().nextDouble()
                        : num(a.get(0)) == null ? Double.NaN : agent.random().nextDouble() * num(a.get(0)));
            default:
                break;
        }
        double[] x = new double[a.size()];
        for (int i = 0; i < x.length; i++) {
            Double d = num(a.get(i));
            if (d == null) {
                return null;
            }
            x[i] = d;
        }
        switch (f.name()) {
            case "math.abs": return new NumberTerm(Math.abs(x[0]));
            case "math.sqrt": return new NumberTerm(Math.sqrt(x[0]));
            case "math.round": return new NumberTerm(Math.round(x[0]));
            case "math.floor": return new NumberTerm(Math.floor(x[0]));
            case "math.ceil": return new NumberTerm(Math.ceil(x[0]));
            case "math.max": return new NumberTerm(Math.max(x[0], x[1]));
            case "math.min": return new NumberTerm(Math.min(x[0], x[1]));
            case "math.log": return new NumberTerm(Math.log(x[0]));
            case "math.sin": return new NumberTerm(Math.sin(x[0]));
            case "math.cos": return new NumberTerm(Math.cos(x[0]));
            case "math.tan": return new NumberTerm(Math.tan(x[0]));
            case "math.asin": return new NumberTerm(Math.asin(x[0]));
            case "math.acos": return new NumberTerm(Math.acos(x[0]));
            case "math.atan": return new NumberTerm(Math.atan(x[0]));
            case "math.atan2": return new NumberTerm(Math.atan2(x[0], x[1]));
            case "math.pow": return new NumberTerm(Math.pow(x[0], x[1]));
            case "math.signum": return new NumberTerm(Math.signum(x[0]));
            default: return null;
        }
    }

    private static Double num(Term t) {
        return t instanceof NumberTerm n ? n.value() : null;
    }

    /**
     * Jason's {@code math.max(L)} and {@code math.min(L)}: the largest or smallest number of the
     * list, its other items skipped. Jason starts the largest at {@code Double.MIN_VALUE}, the
     * smallest positive double, so a list of negative numbers, or of none, gives 4.9E-324 there;
     * kept, since Jason 3.2.0 is the reference.
     */
    private static Term extremeOf(boolean largest, Term t) {
        if (!(t instanceof ListTerm l)) {
            return null;
        }
        double found = largest ? Double.MIN_VALUE : Double.MAX_VALUE;
        for (Term item : l.elements()) {
            if (item instanceof NumberTerm n) {
                found = largest ? Math.max(found, n.value()) : Math.min(found, n.value());
            }
        }
        return new NumberTerm(found);
    }

    private static Term listFunction(String name, Term t) {
        if (!(t instanceof ListTerm l)) {
            return null;
        }
        List<Term> items = l.elements();
        double[] x = new double[items.size()];
        for (int i = 0; i < x.length; i++) {
            Double d = num(items.get(i));
            if (d == null) {
                return null;
            }
            x[i] = d;
        }
        double sum = 0;
        for (double v : x) {
            sum += v;
        }
        switch (name) {
            case "math.sum":
                return new NumberTerm(sum);
            case "math.median": {
                if (x.length == 0) {
                    return null;
                }
                double[] s = x.clone();
                Arrays.sort(s);
                return new NumberTerm(s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2);
            }
            case "math.std_dev": {
                double mean = sum / x.length;
                double sq = 0;
                for (double v : x) {
                    sq += (v - mean) * (v - mean);
                }
                return new NumberTerm(Math.sqrt(sq / (x.length - 1)));
            }
            default:
                return new NumberTerm(sum / x.length);
        }
    }
}
