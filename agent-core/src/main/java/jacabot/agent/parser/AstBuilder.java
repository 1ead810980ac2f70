package jacabot.agent.parser;

import jacabot.agent.parser.AgentSpeakParser.*;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.ArithFunctions;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyStep.Kind;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.Rule;
import jacabot.agent.syntax.SourceInfo;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Trigger;
import jacabot.agent.syntax.TriggerTerm;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/** Turns ANTLR parse trees into our immutable syntax (terms, plans, bodies). */
final class AstBuilder {
    private final String file;
    private final ErrorCollector errors;
    /**
     * Numbers unnamed variables: each {@code _} or {@code _X} read takes a number, as each makes a
     * new variable of Jason's one counter (see {@link AslParser#varCounter()}).
     */
    private AtomicLong varCounter = new AtomicLong();

    /** The namespaces of the file being read (Jason's modules). */
    private Namespaces namespaces = new Namespaces(null, new AtomicInteger());
    /**
     * Whether an argument or a list element is being read: its literals are in the default
     * namespace unless prefixed, as Jason reads them.
     */
    private boolean inTerm;

    /** Functions registered by {@code register_function} so far, as {@code name/arity}. */
    private Set<String> userFunctions = Set.of();

    void setUserFunctions(Set<String> names) {
        userFunctions = names;
    }

    void setVarCounter(AtomicLong counter) {
        varCounter = counter;
    }

    /** {@code _X}: the same variable wherever written in the clause, yet it takes a number, as in Jason. */
    private Var unnamed(String name) {
        varCounter.incrementAndGet();
        return named(name);
    }

    /**
     * The variables written so far, one object per name: equal variables are equal objects, and
     * a unifier finds a variable bound by the same object (say, a plan's N in its trigger and
     * body) at the first comparison. Names are interned, as functors are.
     */
    private final HashMap<String, Var> named = new HashMap<>();

    private Var named(String name) {
        Var v = named.get(name);
        if (v == null) {
            v = new Var(name.intern());
            named.put(v.name(), v);
        }
        return v;
    }

    Namespaces namespaces() {
        return namespaces;
    }

    /** Reads the file in namespace ns (null: the default one), as an included module. */
    void setNamespace(Term ns, AtomicInteger counter) {
        namespaces = new Namespaces(ns, counter);
    }

    AstBuilder(String file, ErrorCollector errors) {
        this.file = file;
        this.errors = errors;
    }

    SourceInfo where(ParserRuleContext ctx) {
        return where(ctx.getStart());
    }

    SourceInfo where(Token t) {
        return new SourceInfo(file, t.getLine(), t.getCharPositionInLine() + 1);
    }

    // ---- clauses -------------------------------------------------------------------------------

    Object belief(BeliefContext ctx) {
        Term head = literal(ctx.literal());
        if (!(head instanceof Literal lit)) {
            errors.add(where(ctx), "a belief must be a literal, not '" + head + "'");
            return Literal.TRUE;
        }
        if (ctx.logExpr() != null) {
            return new Rule(lit, logExpr(ctx.logExpr()));
        }
        return lit;
    }

    Literal initialGoal(InitialGoalContext ctx) {
        Term g = literal(ctx.literal());
        if (g instanceof Literal lit) {
            return lit;
        }
        errors.add(where(ctx), "a variable cannot be a goal");
        return Literal.TRUE;
    }

    Plan plan(PlanContext ctx) {
        Literal label = ctx.planLabel() == null ? null : planLabel(ctx.planLabel());
        Trigger trigger = trigger(ctx.trigger());
        LogExprContext contextCtx = ctx.logExpr().stream().filter(e -> e != ctx.goalCondition).findFirst().orElse(null);
        Term context = contextCtx == null ? null : noTrue(logExpr(contextCtx));
        Term condition = ctx.goalCondition == null ? null : logExpr(ctx.goalCondition);
        BodyTerm body = ctx.planBody() == null ? BodyTerm.EMPTY : withoutLeadingTrue(planBody(ctx.planBody()));
        // Jason's line of a plan (its code_line) is its label's, or else where its context (or goal
        // condition) starts, or else its body
        SourceInfo src = where(ctx.planLabel() != null ? ctx.planLabel() : !ctx.logExpr().isEmpty() ? ctx.logExpr(0)
                : ctx.planBody() != null ? ctx.planBody() : ctx);
        return new Plan(label, trigger, context, body, src, condition);
    }

    /**
     * A plan's body that starts with the action {@code true} starts after it, as Jason reads a plan
     * ({@code +!g <- true.} is a plan with no body; a later {@code true}, or one in a plan term
     * {@code { ... }}, stays an action).
     */
    private static BodyTerm withoutLeadingTrue(BodyTerm body) {
        List<BodyStep> steps = body.steps();
        if (steps.isEmpty() || steps.get(0).kind() != Kind.ACTION || !Literal.TRUE.equals(steps.get(0).term())) {
            return body;
        }
        return new BodyTerm(steps.subList(1, steps.size()));
    }

    /** A context that is just {@code true} is no context, as Jason reads it ({@code +!g : true <- b} prints {@code +!g <- b}). */
    private static Term noTrue(Term context) {
        return Literal.TRUE.equals(context) ? null : context;
    }

    Literal planLabel(PlanLabelContext ctx) {
        if (ctx.literal() != null) {
            Term t = literal(ctx.literal());
            if (t instanceof Literal l) {
                return l;
            }
            errors.add(where(ctx), "a plan label must be an atom");
            return null;
        }
        // @[atomic]: an unnamed label, named by the plan library
        return new Literal("undefined", List.of(), list(ctx.list()).elements(), false);
    }

    Trigger trigger(TriggerContext ctx) {
        Trigger.Op op;
        switch (ctx.op.getText()) {
            case "+": op = Trigger.Op.ADD; break;
            case "-": op = Trigger.Op.DEL; break;
            default: op = Trigger.Op.GOAL_STATE; break;
        }
        Trigger.Type type = Trigger.Type.BELIEF;
        if (ctx.kind != null) {
            type = ctx.kind.getText().equals("!") ? Trigger.Type.ACHIEVE : Trigger.Type.TEST;
        }
        return new Trigger(op, type, literal(ctx.literal()));
    }

    // ---- plan bodies (BodyBuilder) ------------------------------------------------------------

    private final BodyBuilder bodies = new BodyBuilder(this);

    BodyTerm planBody(PlanBodyContext ctx) {
        return bodies.planBody(ctx);
    }

    void error(SourceInfo where, String message) {
        errors.add(where, message);
    }

    // ---- logical and arithmetic expressions ----------------------------------------------------

    Term logExpr(LogExprContext ctx) {
        Term left = logTerm(ctx.logTerm());
        return ctx.logExpr() == null ? left : new LogExpr(LogExpr.Op.OR, left, logExpr(ctx.logExpr()));
    }

    private Term logTerm(LogTermContext ctx) {
        Term left = logFactor(ctx.logFactor());
        return ctx.logTerm() == null ? left : new LogExpr(LogExpr.Op.AND, left, logTerm(ctx.logTerm()));
    }

    private Term logFactor(LogFactorContext ctx) {
        if (ctx instanceof NotFactorContext n) {
            return LogExpr.not(logFactor(n.logFactor()));
        }
        return relExpr(((RelFactorContext) ctx).relExpr());
    }

    private Term relExpr(RelExprContext ctx) {
        Term left = relOperand(ctx.relOperand(0));
        if (ctx.op == null) {
            return left;
        }
        Term right = relOperand(ctx.relOperand(1));
        RelExpr.Op op;
        switch (ctx.op.getText()) {
            case "<": op = RelExpr.Op.LT; break;
            case "<=": op = RelExpr.Op.LTE; break;
            case ">": op = RelExpr.Op.GT; break;
            case ">=": op = RelExpr.Op.GTE; break;
            case "==": op = RelExpr.Op.EQ; break;
            case "\\==": op = RelExpr.Op.DIF; break;
            case "=": op = RelExpr.Op.UNIFY; break;
            default: op = RelExpr.Op.UNIV; break;
        }
        return new RelExpr(op, operand(left), operand(right));
    }

    /**
     * An atom as an operand of a relational expression is a structure for Jason's {@code .structure};
     * an operand is a term, so it leaves the current namespace for the default one, as in Jason.
     */
    private Term operand(Term t) {
        Term ns = inTerm ? null : namespaces.current();
        if (t instanceof Literal l) {
            if (l.ns() != null && l.ns().equals(ns)) {
                l = l.withNs(null);
            }
            return l.asOperandAtom();
        }
        if (t instanceof AnnotatedVar av && av.ns() != null && av.ns().equals(ns)) {
            return av.annots().isEmpty() && av.tail() == null ? av.var() : new AnnotatedVar(av.var(), av.annots(), av.tail());
        }
        return t;
    }

    private Term relOperand(RelOperandContext ctx) {
        if (ctx.arithExpr() != null) {
            return arithExpr(ctx.arithExpr());
        }
        if (ctx.STRING() != null) {
            return string(ctx.STRING().getText());
        }
        if (ctx.list() != null) {
            return list(ctx.list());
        }
        return braceTerm(ctx.braceTerm());
    }

    private Term arithExpr(ArithExprContext ctx) {
        Term t = arithTerm(ctx.arithTerm(0));
        boolean told = false; // Jason stops at an expression's first bad operand: the others are not told
        for (int i = 1; i < ctx.arithTerm().size(); i++) {
            var op = ctx.op.get(i - 1).getText().equals("+") ? ArithExpr.Op.PLUS : ArithExpr.Op.MINUS;
            told = told || operand(t, "ArithExpr", "first", ctx);
            Term right = arithTerm(ctx.arithTerm(i));
            told = told || operand(right, "ArithExpr", "second", ctx);
            t = new ArithExpr(op, t, right, where(ctx));
        }
        return t;
    }

    /**
     * {@return the message of an operand that is no number, named by its grammar rule as Jason names
     * it} ({@link #operand} tells it; a later rule that knows its likely cause finds it by it, {@link #amend})
     */
    static String operandError(String rule, String which, Term t) {
        return rule + ": " + which + " operand '" + t + "' is not numeric or variable";
    }

    /** {@return whether this term is no operand of arithmetic: an atom, a structure or a relation} */
    static boolean notNumeric(Term t) {
        return t instanceof Literal || t instanceof RelExpr || t instanceof LogExpr;
    }

    void amend(SourceInfo where, String message, String more) {
        errors.amend(where, message, more);
    }

    /**
     * An operand of an arithmetic operator as Jason's parser takes it: a number, a variable, an
     * expression or a function; an atom, a structure or a relation there is an error as it reads
     * the file (its message names the grammar rule: ArithExpr for + and -, ArithTerm for *, /, div
     * and mod, ArithFactor for **).
     */
    private boolean operand(Term t, String rule, String which, ParserRuleContext ctx) {
        if (notNumeric(t)) {
            errors.add(where(ctx), operandError(rule, which, t));
            return true;
        }
        return false;
    }

    private Term arithTerm(ArithTermContext ctx) {
        Term t = arithFactor(ctx.arithFactor(0));
        boolean told = false;
        for (int i = 1; i < ctx.arithFactor().size(); i++) {
            ArithExpr.Op op;
            switch (ctx.op.get(i - 1).getText()) {
                case "*": op = ArithExpr.Op.TIMES; break;
                case "/": op = ArithExpr.Op.DIV; break;
                case "div": op = ArithExpr.Op.INTDIV; break;
                default: op = ArithExpr.Op.MOD; break;
            }
            told = told || operand(t, "ArithTerm", "first", ctx);
            Term right = arithFactor(ctx.arithFactor(i));
            told = told || operand(right, "ArithTerm", "second", ctx);
            t = new ArithExpr(op, t, right, where(ctx));
        }
        return t;
    }

    private Term arithFactor(ArithFactorContext ctx) {
        Term base = arithSimple(ctx.arithSimple());
        if (ctx.arithFactor() == null) {
            return base;
        }
        boolean told = operand(base, "ArithFactor", "first", ctx);
        Term exponent = arithFactor(ctx.arithFactor());
        if (!told) {
            operand(exponent, "ArithFactor", "second", ctx);
        }
        return new ArithExpr(ArithExpr.Op.POW, base, exponent, where(ctx));
    }

    private Term arithSimple(ArithSimpleContext ctx) {
        Term t;
        if (ctx.NUMBER() != null) {
            t = new NumberTerm(Double.parseDouble(ctx.NUMBER().getText()));
        } else if (ctx.logExpr() != null) {
            t = logExpr(ctx.logExpr());
        } else {
            t = literal(ctx.literal());
            if (t instanceof Literal l && !l.negated() && l.annots().isEmpty() && l.tail() == null
                    && (ArithFunctions.isFunction(l.functor(), l.arity())
                            || userFunctions.contains(l.functor() + "/" + l.arity()))) {
                t = new ArithFunction(l.functor(), l.args());
            }
        }
        if (ctx.sign == null) {
            return t;
        }
        var op = ctx.sign.getText().equals("-") ? ArithExpr.Op.MINUS : ArithExpr.Op.PLUS;
        if (t instanceof NumberTerm n && op == ArithExpr.Op.MINUS) {
            return new NumberTerm(-n.value());
        }
        if (op == ArithExpr.Op.MINUS && !(t instanceof ArithExpr || t instanceof ArithFunction || t instanceof Var
                || t instanceof AnnotatedVar)) {
            // Jason refuses it as it reads the file ("-p" is no term of its)
            errors.add(where(ctx), "the argument '" + t + "' of operator '-' is not numeric or variable");
        }
        return ArithExpr.unary(op, t, where(ctx));
    }

    // ---- literals and terms --------------------------------------------------------------------

    Term literal(LiteralContext ctx) {
        if (ctx instanceof TrueLiteralContext) {
            return Literal.TRUE;
        }
        if (ctx instanceof FalseLiteralContext) {
            return Literal.FALSE;
        }
        if (ctx instanceof VarLiteralContext v) {
            Term ns = varNs(v.nsPrefix());
            Var var = named(v.VAR().getText());
            return ns == null && v.annots() == null ? var : annotated(var, annotList(v.annots()), ns);
        }
        if (ctx instanceof UnnamedVarLiteralContext u) {
            Term ns = varNs(u.nsPrefix());
            String name = u.UNNAMEDVAR().getText();
            Var var = name.equals("_") ? new Var("_", varCounter.incrementAndGet()) : unnamed(name);
            return ns == null && u.annots() == null ? var : annotated(var, annotList(u.annots()), ns);
        }
        StructureContext s = (StructureContext) ctx;
        // interned, as variable names: the interpreter compares functors and names all the time,
        // and equal strings that are one object compare at once (as .send and its registry key)
        String functor = s.name.getText().intern();
        Term ns = s.nsPrefix() != null ? explicitNs(s.nsPrefix()) : inTerm ? null : namespaces.current();
        boolean outer = inTerm;
        inTerm = true;
        List<Term> args = s.terms() == null ? List.of() : terms(s.terms());
        // b[x,y|T], b[|T]: the annotations as a list, which the literal takes apart (b[] has none)
        Term annots = s.annots() == null ? ListTerm.EMPTY : annotList(s.annots());
        inTerm = outer;
        boolean negated = s.neg != null;
        if (functor.indexOf('.') >= 0 && functor.charAt(0) != '\'') {
            if (!(annots instanceof ListTerm.Empty)) {
                errors.add(where(ctx), "internal actions cannot have annotations");
            }
            if (negated) {
                errors.add(where(ctx), "internal actions cannot be negated");
            }
            ns = null; // as Jason's: internal actions have no namespace
        }
        if (Namespaces.isKeyword(functor, args.size())) {
            ns = null;
        }
        return new Literal(functor, args, List.of(), negated, false, namespaces.map(ns),
                annots instanceof ListTerm.Empty ? null : annots, where(ctx));
    }

    /** {@code ns::}, {@code NS::}, {@code _::}, {@code ::}: the namespace written (null: the default one). */
    private Term explicitNs(NsPrefixContext p) {
        if (p.ns == null) {
            return namespaces.thisNs();
        }
        String text = p.ns.getText();
        text = text.substring(0, text.length() - 2);
        if (p.ns.getType() == AgentSpeakParser.NS_VAR) {
            if (text.startsWith("_")) {
                return text.equals("_") ? new Var("_", varCounter.incrementAndGet()) : unnamed(text);
            }
            return named(text);
        }
        if (text.equals(Literal.DEFAULT_NS_NAME)) {
            return null;
        }
        return text.equals("this_ns") ? namespaces.thisNs() : Literal.atom(text.intern());
    }

    /** A variable's namespace: the one written, or else the current one for a formula (Jason's {@code var(NS)}). */
    private Term varNs(NsPrefixContext p) {
        return namespaces.map(p != null ? explicitNs(p) : inTerm ? null : namespaces.current());
    }

    /** As Jason, the atom {@code this_ns} written as a term names the namespace the file is read in. */
    private Term thisNs(Term t) {
        return t instanceof Literal l && l.isAtom() && l.ns() == null && l.functor().equals("this_ns")
                ? namespaces.thisNsAtom() : t;
    }

    private List<Term> terms(TermsContext ctx) {
        var out = new ArrayList<Term>(ctx.term().size());
        for (TermContext t : ctx.term()) {
            out.add(thisNs(logExpr(t.logExpr())));
        }
        return out;
    }

    Term term(TermContext ctx) {
        return logExpr(ctx.logExpr());
    }

    /** {@code [a, b | T]} as a list, {@code [|T]} as its tail alone; none: {@code []}. */
    private Term annotList(AnnotsContext ctx) {
        if (ctx == null) {
            return ListTerm.EMPTY;
        }
        return ctx.list() != null ? list(ctx.list()) : listTail(ctx.listTail());
    }

    /** {@code V[a, b | T]}: the annotations, and the tail when there is one. */
    private static AnnotatedVar annotated(Var var, Term annots, Term ns) {
        var items = new ArrayList<Term>();
        Term t = annots;
        while (t instanceof ListTerm.Cons c) {
            items.add(c.head());
            t = c.tail();
        }
        return new AnnotatedVar(var, items, t instanceof ListTerm ? null : t, ns);
    }

    ListTerm list(ListContext ctx) {
        boolean outer = inTerm;
        inTerm = true;
        try {
            return listElements(ctx);
        } finally {
            inTerm = outer;
        }
    }

    private ListTerm listElements(ListContext ctx) {
        var items = new ArrayList<Term>();
        for (ListElementContext e : ctx.listElement()) {
            if (e.arithExpr() != null) {
                items.add(thisNs(arithExpr(e.arithExpr())));
            } else if (e.STRING() != null) {
                items.add(string(e.STRING().getText()));
            } else if (e.list() != null) {
                items.add(list(e.list()));
            } else {
                items.add(braceTerm(e.braceTerm()));
            }
        }
        return ListTerm.of(items, ctx.listTail() == null ? ListTerm.EMPTY : listTail(ctx.listTail()));
    }

    private Term listTail(ListTailContext t) {
        if (t.VAR() != null) {
            return named(t.VAR().getText());
        }
        if (t.UNNAMEDVAR() != null) {
            String name = t.UNNAMEDVAR().getText();
            return name.equals("_") ? new Var("_", varCounter.incrementAndGet()) : unnamed(name);
        }
        return list(t.list());
    }

    private Term braceTerm(BraceTermContext ctx) {
        if (ctx.trigger() != null) {
            Trigger trigger = trigger(ctx.trigger());
            boolean hasContext = ctx.logExpr() != null;
            boolean hasBody = ctx.planBody() != null;
            if (ctx.planLabel() == null && !hasContext && !hasBody) {
                return new TriggerTerm(trigger);
            }
            Term label = null;
            if (ctx.planLabel() != null) {
                // in a plan term the label may be a variable: {@L +!g <- B}
                Term t = ctx.planLabel().literal() == null ? null : literal(ctx.planLabel().literal());
                label = t instanceof Var ? t : planLabel(ctx.planLabel());
            }
            Term context = hasContext ? noTrue(logExpr(ctx.logExpr())) : null;
            Term body = hasBody ? planBody(ctx.planBody()) : BodyTerm.EMPTY;
            if (body instanceof BodyTerm b && b.steps().size() == 1 && b.steps().get(0).kind() == BodyStep.Kind.ACTION
                    && b.steps().get(0).term() instanceof Var v) {
                body = v; // <- B: the whole body is a variable
            }
            return new PlanTerm(label, trigger, context, body, where(ctx));
        }
        if (ctx.planBody() == null) {
            return BodyTerm.EMPTY;
        }
        BodyTerm body = planBody(ctx.planBody());
        if (ctx.logExpr() != null) {
            // { head :- body }: a rule as a term
            if (body.steps().size() == 1 && body.steps().get(0).term() instanceof Literal head) {
                return Literal.of(Literal.RULE_TERM, head, logExpr(ctx.logExpr()));
            }
            errors.add(where(ctx), "wrong place for a rule");
        }
        return body;
    }

    /** Jason reads only two escapes in strings: {@code \\n} and {@code \\"}. */
    static StringTerm string(String token) {
        String raw = token.substring(1, token.length() - 1);
        return new StringTerm(raw.replace("\\n", "\n").replace("\\\"", "\""));
    }
}
