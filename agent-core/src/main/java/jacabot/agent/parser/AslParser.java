package jacabot.agent.parser;

import jacabot.agent.parser.AgentSpeakParser.ComponentContext;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.NumberTerm;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.SourceInfo;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.ParseCancellationException;

/**
 * Reads AgentSpeak: whole agent programs (with {@code { include("f.asl") }} directives),
 * single terms and single plans. Every error carries {@code file:line:col}.
 */
public final class AslParser {
    private final List<Path> sourcePath;
    private final SourceResolver includes;
    /** Functions registered while reading one program (its included files share them). */
    private List<AgentProgram.UserFunction> userFunctions = new ArrayList<>();
    private Set<String> userFunctionNames = new HashSet<>();

    /** @param sourcePath directories searched for included files, after the including file's own */
    public AslParser(List<Path> sourcePath) {
        this.sourcePath = List.copyOf(sourcePath);
        this.includes = SourceResolver.files(this.sourcePath);
    }

    /** @param includes where included sources are read from (e.g. class path resources) */
    public AslParser(SourceResolver includes) {
        this.sourcePath = List.of();
        this.includes = includes;
    }

    /** @param sourcePath directories of {@link #locate}; @param includes where included sources are read from */
    public AslParser(List<Path> sourcePath, SourceResolver includes) {
        this.sourcePath = List.copyOf(sourcePath);
        this.includes = includes;
    }

    public AslParser() {
        this(List.of());
    }

    /** {@return the file found in the source path (or as given), or null} */
    public Path locate(String file) {
        return SourceResolver.findFile(file, null, sourcePath);
    }

    /** Parses an agent program from a file. */
    public AgentProgram parseFile(Path file) throws AslSyntaxException, IOException {
        return parse(new SourceResolver.Source(file.toString(), Files.readString(file, StandardCharsets.UTF_8),
                file.toAbsolutePath().normalize().toString()));
    }

    /** Parses an agent program whose includes are found from its location by this parser's resolver. */
    public AgentProgram parse(SourceResolver.Source source) throws AslSyntaxException, IOException {
        userFunctions = new ArrayList<>();
        userFunctionNames = new HashSet<>();
        return parse(source, new HashSet<>(), null);
    }

    /**
     * Parses an agent program from a file as a module in namespace ns (Jason's {@code .include(F, NS)});
     * null or {@code default}: the default namespace.
     */
    public AgentProgram parseFile(Path file, Term ns) throws AslSyntaxException, IOException {
        userFunctions = new ArrayList<>();
        userFunctionNames = new HashSet<>();
        return parse(new SourceResolver.Source(file.toString(), Files.readString(file, StandardCharsets.UTF_8),
                file.toAbsolutePath().normalize().toString()), new HashSet<>(), ns);
    }

    /**
     * Jason's one counter of fresh variables ({@code _N}): the unnamed variables this parser reads
     * and, through {@link #varCounter()}, those the agents of its multi-agent system make (renaming
     * apart), so that they get the numbers Jason's would.
     */
    private final AtomicLong varCounter = new AtomicLong();

    /** {@return the counter that numbers fresh variables, shared by the agents this parser reads programs for} */
    public AtomicLong varCounter() {
        return varCounter;
    }

    /** Numbers the local namespaces and the anonymous includes of the files this parser reads. */
    private final AtomicInteger nsCounter = new AtomicInteger();

    /**
     * {@return whether this parser has read nothing yet} (no fresh variable or namespace numbered,
     * no function registered): what {@link #resume} needs
     */
    public boolean isFresh() {
        return varCounter.get() == 0 && nsCounter.get() == 0 && userFunctions.isEmpty();
    }

    /** {@return the namespaces numbered so far ({@link #freshNamespace})} */
    public int namespacesNumbered() {
        return nsCounter.get();
    }

    /**
     * A fresh parser takes the state another fresh parser of the same resolver was left in by
     * reading {@code program}: its variable and namespace counters at {@code vars} and
     * {@code namespaces}, and the program's registered functions. So a program read once can be
     * handed to the next agent with the parser it would have had after reading it itself.
     *
     * @throws IllegalStateException when this parser is not fresh
     */
    public void resume(AgentProgram program, long vars, int namespaces) {
        if (!isFresh()) {
            throw new IllegalStateException("a parser that has read something cannot take another's state");
        }
        varCounter.set(vars);
        nsCounter.set(namespaces);
        userFunctions = new ArrayList<>(program.functions());
        userFunctionNames = new HashSet<>();
        program.functions().forEach(f -> userFunctionNames.add(f.name() + "/" + f.arity()));
    }

    /** {@return a new namespace name, as Jason gives to {@code include(F, Var)}} */
    public Literal freshNamespace() {
        return Namespaces.fresh(nsCounter);
    }

    private AgentProgram parse(SourceResolver.Source source, Set<String> including, Term ns) throws AslSyntaxException, IOException {
        String key = source.location() != null ? source.location() : source.name();
        including.add(key);
        try {
            return parse(source.text(), source.name(), source, including, ns);
        } finally {
            including.remove(key);
        }
    }

    /** Parses an agent program held in a string; {@code file} names it in error messages. */
    public AgentProgram parse(String text, String file) throws AslSyntaxException {
        userFunctions = new ArrayList<>();
        userFunctionNames = new HashSet<>();
        try {
            return parse(text, file, new SourceResolver.Source(file, text, null), new HashSet<>(), null);
        } catch (IOException e) {
            throw new AslSyntaxException(List.of(new SyntaxError(
                    new SourceInfo(file, 0, 0), e.getMessage())));
        }
    }

    private AgentProgram parse(String text, String file, SourceResolver.Source from, Set<String> including, Term ns)
            throws AslSyntaxException, IOException {
        var errors = new ErrorCollector(file);
        var tree = agentTree(text, errors);
        var builder = new AstBuilder(file, errors);
        builder.setNamespace(ns, nsCounter);
        builder.setVarCounter(varCounter);
        builder.setUserFunctions(userFunctionNames);
        var beliefs = new ArrayList<Object>();
        var goals = new ArrayList<Literal>();
        var plans = new ArrayList<Plan>();
        // plans inside { begin P } ... { end }, innermost last, each with its pattern and position
        var blocks = new ArrayDeque<Block>();
        if (errors.errors().isEmpty()) {
            for (ComponentContext c : tree.component()) {
                if (c.directive() != null && c.directive().begin != null) {
                    Term d = builder.literal(c.directive().literal());
                    if (isNamespace(d)) {
                        // { begin namespace(ns) } ... { end }: the plans stay where they are
                        String error = builder.namespaces().begin((Literal) d);
                        if (error != null) {
                            errors.add(builder.where(c), error);
                        }
                        blocks.push(new Block((Literal) d, null, builder.where(c)));
                        continue;
                    }
                    blocks.push(new Block(d instanceof Literal l ? l : Literal.atom(String.valueOf(d)), plans, builder.where(c)));
                    plans = new ArrayList<>();
                } else if (c.directive() != null && isEnd(builder.literal(c.directive().literal()))) {
                    Block b = blocks.poll();
                    if (b == null) {
                        errors.add(builder.where(c), "{ end } without { begin ... }");
                        continue;
                    }
                    if (b.outer == null) {
                        builder.namespaces().end();
                        continue;
                    }
                    List<Plan> made = GoalPatterns.apply(b.pattern, plans, this);
                    if (made == null) {
                        errors.add(b.where, "unknown directive '" + b.pattern + "'");
                        made = plans;
                    }
                    plans = b.outer;
                    plans.addAll(made);
                } else if (c.belief() != null) {
                    beliefs.add(builder.belief(c.belief()));
                } else if (c.initialGoal() != null) {
                    goals.add(builder.initialGoal(c.initialGoal()));
                } else if (c.plan() != null) {
                    plans.add(builder.plan(c.plan()));
                } else {
                    Term d = builder.literal(c.directive().literal());
                    if (isNamespace(d)) {
                        // { namespace(ns, local) }: declares ns (local names are made unique here)
                        String error = builder.namespaces().begin((Literal) d);
                        if (error != null) {
                            errors.add(builder.where(c), error);
                        } else {
                            builder.namespaces().end();
                        }
                    } else if (d instanceof Literal l && l.functor().equals("include") && l.arity() >= 1
                            && l.arg(0) instanceof StringTerm name) {
                        SourceResolver.Source included = includes.find(name.value(), from);
                        if (included == null) {
                            errors.add(builder.where(c), "included file '" + name.value() + "' not found");
                        } else if (including.contains(included.location())) {
                            errors.add(builder.where(c), "file '" + name.value() + "' includes itself");
                        } else {
                            AgentProgram sub = parse(included, including, includeNamespace(l));
                            beliefs.addAll(sub.beliefs());
                            goals.addAll(sub.goals());
                            plans.addAll(sub.plans());
                        }
                    } else if (d instanceof Literal l && l.functor().equals("register_function")) {
                        AgentProgram.UserFunction f = userFunction(l);
                        if (f == null) {
                            errors.add(builder.where(c), "register_function needs a name, an arity and a predicate: '" + d + "'");
                        } else {
                            userFunctions.add(f);
                            userFunctionNames.add(f.name() + "/" + f.arity());
                        }
                    } else {
                        errors.add(builder.where(c), "unknown directive '" + d + "'");
                    }
                }
            }
        }
        if (!blocks.isEmpty() && errors.errors().isEmpty()) {
            errors.add(blocks.peek().where, "{ begin " + blocks.peek().pattern + " } without { end }");
        }
        if (!errors.errors().isEmpty()) {
            throw new AslSyntaxException(errors.errors());
        }
        return new AgentProgram(file, beliefs, goals, plans, userFunctions);
    }

    /** {@code register_function("f", N, "p")} (Jason's rule-defined function; its default predicate is f's name). */
    private static AgentProgram.UserFunction userFunction(Literal l) {
        if (l.arity() < 2 || !(l.arg(0) instanceof StringTerm name)
                || !(l.arg(1) instanceof NumberTerm n)) {
            return null;
        }
        String predicate = l.arity() > 2 && l.arg(2) instanceof StringTerm p ? p.value() : name.value();
        return new AgentProgram.UserFunction(name.value(), (int) n.value(), predicate);
    }

    /** An open {@code { begin P }}: its pattern, the plans before it, and where it was opened. */
    private record Block(Literal pattern, ArrayList<Plan> outer, SourceInfo where) {
    }

    private static boolean isNamespace(Term d) {
        return d instanceof Literal l && l.functor().equals("namespace");
    }

    /**
     * The namespace of {@code include(F, NS)}: NS, a new one when NS is a variable, and without
     * NS the one the directive is written in.
     */
    private Term includeNamespace(Literal include) {
        if (include.arity() < 2) {
            return include.ns();
        }
        Term ns = include.arg(1);
        return ns instanceof Literal a && a.isAtom() ? a : freshNamespace();
    }

    private static boolean isEnd(Term d) {
        return d instanceof Literal l && l.functor().equals("end") && l.arity() == 0;
    }

    /** Parses one term, e.g. for {@code .term2string(T, "f(x)")}. */
    public Term parseTerm(String text) throws AslSyntaxException {
        Term plain = PlainTerm.read(text);
        return plain != null ? plain : parseTermByGrammar(text);
    }

    /** {@link #parseTerm} without the shortcut for plain atoms and numbers. */
    Term parseTermByGrammar(String text) throws AslSyntaxException {
        var errors = new ErrorCollector("<term>");
        var parser = newParser(text, errors);
        var tree = parser.termOnly();
        Term t = errors.errors().isEmpty() ? builder("<term>", errors).term(tree.term()) : null;
        if (!errors.errors().isEmpty()) {
            throw new AslSyntaxException(errors.errors());
        }
        return t;
    }

    /** Parses one plan, e.g. for {@code .add_plan("+!g <- ...")}. */
    public Plan parsePlan(String text) throws AslSyntaxException {
        var errors = new ErrorCollector("<plan>");
        var parser = newParser(text, errors);
        var tree = parser.planOnly();
        Plan p = errors.errors().isEmpty() ? builder("<plan>", errors).plan(tree.plan()) : null;
        if (!errors.errors().isEmpty()) {
            throw new AslSyntaxException(errors.errors());
        }
        return p;
    }

    private AstBuilder builder(String name, ErrorCollector errors) {
        var b = new AstBuilder(name, errors);
        b.setVarCounter(varCounter);
        return b;
    }

    /**
     * Parses a program in ANTLR's two stages: SLL prediction first, which gives the tree LL would
     * give or stops at the first error, and full LL again only then (for the errors, or for input
     * that needs it). SLL does a fraction of LL's work when the parser starts cold, as it does at
     * every launch.
     */
    private static AgentSpeakParser.AgentContext agentTree(String text, ErrorCollector errors) {
        var quiet = new ErrorCollector("");
        AgentSpeakParser sll = newParser(text, quiet);
        sll.removeErrorListeners();
        sll.setErrorHandler(new BailErrorStrategy());
        sll.getInterpreter().setPredictionMode(PredictionMode.SLL);
        try {
            AgentSpeakParser.AgentContext tree = sll.agent();
            if (quiet.errors().isEmpty()) {
                return tree;
            }
        } catch (ParseCancellationException e) {
            // an error, or input SLL cannot decide: parse again with LL
        }
        return newParser(text, errors).agent();
    }

    private static AgentSpeakParser newParser(String text, ErrorCollector errors) {
        var lexer = new AgentSpeakLexer(CharStreams.fromString(text));
        lexer.removeErrorListeners();
        lexer.addErrorListener(errors);
        var parser = new AgentSpeakParser(new CommonTokenStream(lexer));
        parser.removeErrorListeners();
        parser.addErrorListener(errors);
        return parser;
    }
}
