package jacabot.agent.parser;

import jacabot.agent.parser.AgentSpeakParser.ComponentContext;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import jacabot.agent.syntax.StringTerm;
import jacabot.agent.syntax.Term;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;

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

    public AslParser() {
        this(List.of());
    }

    /** {@return the file found in the source path (or as given), or null} */
    public Path locate(String file) {
        for (Path dir : sourcePath) {
            Path p = dir.resolve(file);
            if (java.nio.file.Files.isRegularFile(p)) {
                return p;
            }
        }
        Path p = Path.of(file);
        return java.nio.file.Files.isRegularFile(p) ? p : null;
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
        return parse(source, new HashSet<>());
    }

    private AgentProgram parse(SourceResolver.Source source, Set<String> including) throws AslSyntaxException, IOException {
        String key = source.location() != null ? source.location() : source.name();
        including.add(key);
        try {
            return parse(source.text(), source.name(), source, including);
        } finally {
            including.remove(key);
        }
    }

    /** Parses an agent program held in a string; {@code file} names it in error messages. */
    public AgentProgram parse(String text, String file) throws AslSyntaxException {
        userFunctions = new ArrayList<>();
        userFunctionNames = new HashSet<>();
        try {
            return parse(text, file, new SourceResolver.Source(file, text, null), new HashSet<>());
        } catch (IOException e) {
            throw new AslSyntaxException(List.of(new SyntaxError(
                    new jacabot.agent.syntax.SourceInfo(file, 0, 0), e.getMessage())));
        }
    }

    private AgentProgram parse(String text, String file, SourceResolver.Source from, Set<String> including)
            throws AslSyntaxException, IOException {
        var errors = new ErrorCollector(file);
        AgentSpeakParser parser = newParser(text, errors);
        var tree = parser.agent();
        var builder = new AstBuilder(file, errors);
        builder.setUserFunctions(userFunctionNames);
        var beliefs = new ArrayList<Object>();
        var goals = new ArrayList<Literal>();
        var plans = new ArrayList<Plan>();
        // plans inside { begin P } ... { end }, innermost last, each with its pattern and position
        var blocks = new java.util.ArrayDeque<Block>();
        if (errors.errors().isEmpty()) {
            for (ComponentContext c : tree.component()) {
                if (c.directive() != null && c.directive().begin != null) {
                    Term d = builder.literal(c.directive().literal());
                    blocks.push(new Block(d instanceof Literal l ? l : Literal.atom(String.valueOf(d)), plans, builder.where(c)));
                    plans = new ArrayList<>();
                } else if (c.directive() != null && isEnd(builder.literal(c.directive().literal()))) {
                    Block b = blocks.poll();
                    if (b == null) {
                        errors.add(builder.where(c), "{ end } without { begin ... }");
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
                    if (d instanceof Literal l && l.functor().equals("include") && l.arity() >= 1
                            && l.arg(0) instanceof StringTerm name) {
                        SourceResolver.Source included = includes.find(name.value(), from);
                        if (included == null) {
                            errors.add(builder.where(c), "included file '" + name.value() + "' not found");
                        } else if (including.contains(included.location())) {
                            errors.add(builder.where(c), "file '" + name.value() + "' includes itself");
                        } else {
                            AgentProgram sub = parse(included, including);
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
                || !(l.arg(1) instanceof jacabot.agent.syntax.NumberTerm n)) {
            return null;
        }
        String predicate = l.arity() > 2 && l.arg(2) instanceof StringTerm p ? p.value() : name.value();
        return new AgentProgram.UserFunction(name.value(), (int) n.value(), predicate);
    }

    /** An open {@code { begin P }}: its pattern, the plans before it, and where it was opened. */
    private record Block(Literal pattern, ArrayList<Plan> outer, jacabot.agent.syntax.SourceInfo where) {
    }

    private static boolean isEnd(Term d) {
        return d instanceof Literal l && l.functor().equals("end") && l.arity() == 0;
    }

    /** Parses one term, e.g. for {@code .term2string(T, "f(x)")}. */
    public Term parseTerm(String text) throws AslSyntaxException {
        var errors = new ErrorCollector("<term>");
        var parser = newParser(text, errors);
        var tree = parser.termOnly();
        Term t = errors.errors().isEmpty() ? new AstBuilder("<term>", errors).term(tree.term()) : null;
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
        Plan p = errors.errors().isEmpty() ? new AstBuilder("<plan>", errors).plan(tree.plan()) : null;
        if (!errors.errors().isEmpty()) {
            throw new AslSyntaxException(errors.errors());
        }
        return p;
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
