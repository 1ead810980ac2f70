package jacabot.agent.runtime;

import jacabot.agent.parser.SyntaxError;
import jacabot.agent.semantics.Clock;
import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.parser.SourceResolver;
import jacabot.agent.semantics.Agent;
import jacabot.agent.semantics.AgentArch;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.ListTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.SourceInfo;
import jacabot.agent.syntax.Term;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Builds a {@link LocalMAS} from a {@code .mas2j} project or a single {@code .asl} file (a
 * one-agent system named after the file) and runs it until {@code .stopMAS}.
 */
public final class MasLauncher {
    /** A problem with the user's input: printed without a stack trace, exit code 2. */
    public static final class UserError extends Exception {
        private static final long serialVersionUID = 1L;

        public UserError(String message) {
            super(message);
        }
    }

    private final PrintStream out;
    private final long seed;
    private final boolean stepping;

    public MasLauncher(PrintStream out, long seed, boolean stepping) {
        this.out = out;
        this.seed = seed;
        this.stepping = stepping;
    }

    /** Where a project's included sources come from, given its source path (default: its files). */
    private Function<List<Path>, SourceResolver> includes = SourceResolver::files;

    /** Reads included sources with another resolver (e.g. {@code jacabot test}'s, which adds its test library). */
    public MasLauncher includes(Function<List<Path>, SourceResolver> resolver) {
        this.includes = resolver;
        return this;
    }

    /** The agent name for a lone {@code .asl} file: {@code 23_interleave.asl} runs as {@code interleave}. */
    public static String agentNameFor(Path asl) {
        String base = asl.getFileName().toString().replaceFirst("\\.asl$", "");
        base = base.replaceFirst("^[0-9]+_", "");
        if (base.isEmpty()) {
            return "agent";
        }
        return Character.toLowerCase(base.charAt(0)) + base.substring(1);
    }

    /** Loads the system described by a file. */
    public LocalMAS load(Path file) throws UserError {
        if (Files.isDirectory(file)) {
            // a newcomer's first try is the example's folder: name the projects in it
            var projects = new ArrayList<String>();
            try (var in = Files.list(file)) {
                in.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".mas2j") || n.endsWith(".jcm")).sorted()
                        .forEach(n -> projects.add(file.resolve(n).toString()));
            } catch (IOException e) {
                // as a folder without projects
            }
            throw new UserError(file + ": a folder, not a project: "
                    + (projects.isEmpty() ? "give a .mas2j, a .jcm or an .asl file" : "run " + String.join(" or ", projects)));
        }
        if (!Files.isRegularFile(file)) {
            throw new UserError(file + ": no such file");
        }
        String name = file.getFileName().toString();
        try {
            var mas = new LocalMAS(Clock.wall(), out, seed);
            ProjectReader reader = name.endsWith(".mas2j") || name.endsWith(".asl") ? null : ProjectReader.forFile(file);
            if (name.endsWith(".mas2j") || reader != null) {
                MasProject project;
                try {
                    project = reader != null ? reader.read(file) : Mas2jReader.read(file);
                } catch (AslSyntaxException e) {
                    // Jason's console line for a project it cannot read; our located errors follow on stderr
                    out.println("[RunLocalMAS] Error parsing file file:" + file + "!");
                    throw e;
                }
                if (project.environment() != null) {
                    mas.setEnvironment(newInstance(project.environment(), Environment.class), project.environmentArgs());
                } else {
                    mas.setEnvironment(new DefaultEnvironment(), List.of());
                }
                if (reader != null) {
                    reader.prepare(mas);
                }
                var sourcePath = new ArrayList<Path>(project.aslSourcePath());
                sourcePath.add(project.directory());
                SourceResolver resolver = includes.apply(sourcePath);
                var parser = new AslParser(sourcePath, reader == null ? resolver : reader.includes(resolver));
                for (MasProject.AgentSpec spec : project.agents()) {
                    Path asl = locate(spec.file(), sourcePath, file);
                    AgentProgram program = adapted(reader, spec, withOptions(parser.parseFile(asl), spec, parser, file, reader), parser);
                    Function<LocalArch, AgentArch> arch = spec.archClass() == null ? null : archFactory(spec.archClass());
                    for (int k = 1; k <= spec.instances(); k++) {
                        String agName = mas.newAgentName(spec.instances() > 1 ? spec.name() + k : spec.name());
                        if (k > 1) {
                            // as Jason, each instance reads its source: its own unnamed variables and local namespaces
                            program = adapted(reader, spec, withOptions(parser.parseFile(asl), spec, parser, file, reader), parser);
                        }
                        Agent created = mas.createAgent(agName, program, parser, arch);
                        if ("0".equals(spec.options().get("verbose"))) {
                            created.setVerbosity(0);
                        }
                    }
                }
            } else {
                mas.setEnvironment(new DefaultEnvironment(), List.of());
                var parser = new AslParser(List.of(file.toAbsolutePath().getParent()));
                AgentProgram program = parser.parseFile(file);
                mas.createAgent(agentNameFor(file), program, parser, null);
            }
            return mas;
        } catch (AslSyntaxException e) {
            throw new UserError(e.getMessage());
        } catch (NoSuchFileException e) {
            throw new UserError(e.getFile() + ": no such file");
        } catch (IOException e) {
            throw new UserError(file + ": " + e.getMessage());
        }
    }

    /**
     * The {@code beliefs="b(1), c"} and {@code goals="g"} options of a {@code .mas2j} agent add
     * initial beliefs and goals, before the file's (as Jason 3.2.0 orders them).
     *
     * @param project the project file, named in the error when an option cannot be read
     * @throws UserError {@code PROJECT: agent A's beliefs "x(": cannot read ...}: the
     *         option's text is read alone, so its own line and column would point nowhere
     */
    static AgentProgram withOptions(AgentProgram p, MasProject.AgentSpec spec, AslParser parser, Path project,
            ProjectReader reader) throws UserError {
        String beliefs = spec.options().get("beliefs");
        String goals = spec.options().get("goals");
        if (beliefs == null && goals == null) {
            return p;
        }
        var bs = new ArrayList<Object>();
        var gs = new ArrayList<Literal>();
        if (beliefs != null && !beliefs.isBlank()) {
            bs.addAll(optionTerms(parser, beliefs, "beliefs", spec, project, reader));
        }
        bs.addAll(p.beliefs());
        if (goals != null && !goals.isBlank()) {
            for (Term t : optionTerms(parser, goals, "goals", spec, project, reader)) {
                gs.add((Literal) t);
            }
        }
        gs.addAll(p.goals());
        return new AgentProgram(p.file(), bs, gs, p.plans(), p.functions());
    }

    private static AgentProgram adapted(ProjectReader reader, MasProject.AgentSpec spec, AgentProgram p, AslParser parser)
            throws UserError {
        return reader == null ? p : reader.adapt(spec, p, parser);
    }

    private static List<Term> optionTerms(AslParser parser, String text, String option, MasProject.AgentSpec spec,
            Path project, ProjectReader reader) throws UserError {
        try {
            return termsOf(parser, text);
        } catch (AslSyntaxException e) {
            // the first error, without the position inside the option's text read as a term: the
            // text is read as "[TEXT]", so its ']' and its columns (one on) are not the user's
            String why = e.errors().isEmpty() ? e.getMessage() : e.errors().get(0).message();
            why = why.replace("before ']'", "before the option's end").replace("'|', ',' or ']'", "',' or the option's end");
            Matcher at = Pattern.compile(" at 1:(\\d+)").matcher(why);
            why = at.find() ? at.replaceFirst(" at column " + (Integer.parseInt(at.group(1)) - 1)) : why;
            String place = reader == null ? null : reader.optionPlace(spec, option);
            throw new UserError((place != null ? place + ": error" : project.toString()) + ": agent " + spec.name() + "'s "
                    + option + " \"" + text.strip() + "\": " + why);
        }
    }

    private static List<Term> termsOf(AslParser parser, String text) throws AslSyntaxException {
        Term list = parser.parseTerm("[" + text + "]");
        var out = new ArrayList<Term>();
        if (list instanceof ListTerm l) {
            for (Term t : l.elements()) {
                if (!(t instanceof Literal)) {
                    throw new AslSyntaxException(List.of(new SyntaxError(
                            SourceInfo.NONE, "'" + t + "' is not a literal in the option '" + text + "'")));
                }
                out.add(t);
            }
        }
        return out;
    }

    /** Loads and runs until {@code .stopMAS}. */
    public void run(Path file) throws UserError, InterruptedException {
        LocalMAS mas = load(file);
        if (stepping) {
            mas.runStepping();
        } else {
            mas.runThreads();
        }
    }

    private static Path locate(String file, List<Path> sourcePath, Path project) throws UserError {
        for (Path dir : sourcePath) {
            Path p = dir.resolve(file);
            if (Files.isRegularFile(p)) {
                return p;
            }
        }
        // the folders as the user wrote them, relative to here: no absolute path of this machine when not needed
        Path here = Path.of("").toAbsolutePath();
        var looked = new ArrayList<String>();
        for (Path dir : sourcePath) {
            Path a = dir.toAbsolutePath().normalize();
            String shown = a.startsWith(here) ? here.relativize(a).toString() : a.toString();
            looked.add(shown.isEmpty() ? "." : shown);
        }
        throw new UserError(project + ": agent source '" + file + "' not found (looked in " + String.join(", ", looked) + ")");
    }

    private static <T> T newInstance(String className, Class<T> type) throws UserError {
        try {
            Class<?> c = Class.forName(className);
            if (!type.isAssignableFrom(c)) {
                throw new UserError("class " + className + " is not a " + type.getSimpleName());
            }
            return type.cast(c.getConstructor().newInstance());
        } catch (ClassNotFoundException e) {
            throw new UserError("class " + className + " not found" + MovedClasses.hint(className));
        } catch (ReflectiveOperationException e) {
            throw new UserError("cannot create " + className + ": " + e);
        }
    }

    /** An {@code agentArchClass} must have a public constructor taking the {@link LocalArch} it wraps. */
    private static Function<LocalArch, AgentArch> archFactory(String className) throws UserError {
        try {
            Class<?> c = Class.forName(className);
            if (!AgentArch.class.isAssignableFrom(c)) {
                throw new UserError("class " + className + " is not an agent architecture");
            }
            var ctor = c.getConstructor(LocalArch.class);
            return local -> {
                try {
                    return (AgentArch) ctor.newInstance(local);
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException("cannot create " + className, e);
                }
            };
        } catch (ClassNotFoundException e) {
            throw new UserError("agent architecture class " + className + " not found" + MovedClasses.hint(className));
        } catch (NoSuchMethodException e) {
            throw new UserError("agent architecture class " + className + " needs a constructor (LocalArch)");
        }
    }
}
