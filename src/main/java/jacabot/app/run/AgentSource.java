package jacabot.app.run;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.parser.SourceResolver;
import jacabot.agent.parser.SyntaxError;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.SourceInfo;
import jacabot.robot.Experiment;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * An agent program as the launcher loads it: its text, the name it goes by in messages and logs,
 * and where its {@code { include("...") }} directives are read from: beside it on the class path
 * for the packaged agents ({@code /asl/NAME.asl} in the agents jar), beside it on disk for a file.
 */
public record AgentSource(SourceResolver.Source source, SourceResolver includes) {
    /** The packaged agents' folder on the class path (agents/src/main/asl in the repository). */
    private static final String PACKAGED = "asl/";
    /** The packaged agents' includes: class path resources, which do not change while the process runs. */
    private static final SourceResolver PACKAGED_INCLUDES = SourceResolver.resources(AgentSource.class.getClassLoader());

    /** {@return the packaged agent of an experiment, named {@code NAME.asl}} */
    public static AgentSource packaged(Experiment e) {
        return packaged(e, e.id() + ".asl");
    }

    /** {@return the packaged agent of an experiment, named {@code name} in messages and logs} */
    public static AgentSource packaged(Experiment e, String name) {
        return resource(e.agentResource(), name);
    }

    /**
     * {@return a packaged agent, e.g. {@code /asl/as-published/navigation.asl}}
     * @throws UncheckedIOException when it is not on the class path (a broken installation)
     */
    public static AgentSource resource(String resource, String name) {
        String location = resource.startsWith("/") ? resource.substring(1) : resource;
        ClassLoader loader = AgentSource.class.getClassLoader();
        try (InputStream in = loader.getResourceAsStream(location)) {
            if (in == null) {
                throw new IOException("no agent " + resource + " on the class path");
            }
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            return new AgentSource(new SourceResolver.Source(name, text, location), PACKAGED_INCLUDES);
        } catch (IOException ex) {
            throw new UncheckedIOException(ex);
        }
    }

    /**
     * {@return an agent file, named as given; it includes files beside it, then from the working
     * directory, then the packaged agents' own (so a copy of a packaged agent keeps its
     * {@code { include("skills/initial-phase.asl") }} wherever it is)}
     */
    public static AgentSource file(Path file) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        return new AgentSource(new SourceResolver.Source(file.toString(), text, file.toAbsolutePath().normalize().toString()),
                filesThenPackaged(AgentSource.class.getClassLoader()));
    }

    /** Files (absolute locations) first, then the packaged agents' folder; a packaged source's includes stay packaged. */
    private static SourceResolver filesThenPackaged(ClassLoader loader) {
        SourceResolver files = SourceResolver.files(List.of());
        SourceResolver packaged = SourceResolver.resources(loader);
        var beside = new SourceResolver.Source("agents/src/main/asl/", "", PACKAGED);
        return (file, from) -> {
            if (from != null && from.location() != null && from.location().startsWith(PACKAGED)) {
                return packaged.find(file, from);
            }
            SourceResolver.Source found = files.find(file, from);
            return found != null ? found : packaged.find(file, beside);
        };
    }

    /** {@return a program given as text (a probe, a test), named {@code name}; it can include files only by their path} */
    public static AgentSource text(String name, String text) {
        return new AgentSource(new SourceResolver.Source(name, text, null), SourceResolver.files(List.of()));
    }

    /** {@return the name in messages and logs} */
    public String name() {
        return source.name();
    }

    /** {@return the agent's own text (without what it includes)} */
    public String text() {
        return source.text();
    }

    /** {@return the same agent with its text changed (e.g. a test's variant); includes are found as before} */
    public AgentSource withText(String text) {
        return new AgentSource(new SourceResolver.Source(source.name(), text, source.location()), includes);
    }

    /** {@return a parser that reads this agent's includes from where the agent came from} */
    public AslParser parser() {
        return new AslParser(includes);
    }

    /**
     * {@return the program, its includes read in} A fresh parser of a packaged agent's (its text and
     * includes from the class path, which do not change while the process runs; {@link #parser()})
     * reads it once per process: later, the program read then is handed over, with the parser
     * left as reading it would leave it ({@link AslParser#resume}: its fresh variables' and
     * namespaces' numbers, its functions), so each run gets the same program and numbers as if it
     * had read it itself. The program is immutable, so runs on several threads share it. Not in
     * Jason, which reads an agent's source for each agent: a sweep or a bench makes hundreds of
     * runs of one agent, and the parser's code, hot only after many runs, kept C2 compiling in a
     * bench's later runs (docs/performance.md §25). An agent read from files is read each time (its includes may change).
     */
    public AgentProgram parse(AslParser parser) throws AslSyntaxException {
        boolean fresh = includes == PACKAGED_INCLUDES && parser.isFresh();
        if (fresh) {
            Parsed p = ParsedPrograms.get(this);
            if (p != null) {
                parser.resume(p.program(), p.vars(), p.namespaces());
                return p.program();
            }
        }
        try {
            AgentProgram program = parser.parse(source);
            if (fresh) {
                ParsedPrograms.put(this, new Parsed(program, parser.varCounter().get(), parser.namespacesNumbered()));
            }
            return program;
        } catch (IOException e) {
            throw new AslSyntaxException(List.of(new SyntaxError(new SourceInfo(name(), 0, 0),
                    "cannot read an included file: " + e.getMessage())));
        }
    }

    /** {@return this agent's source and every source it includes, in the order they are read} */
    public List<SourceResolver.Source> sources() throws AslSyntaxException {
        var read = new ArrayList<SourceResolver.Source>(List.of(source));
        SourceResolver recording = (file, from) -> {
            SourceResolver.Source s = includes.find(file, from);
            if (s != null) {
                read.add(s);
            }
            return s;
        };
        new AgentSource(source, recording).parse(new AslParser(recording));
        return read;
    }

    /** A program as a fresh parser read it, and the parser's counters after. */
    record Parsed(AgentProgram program, long vars, int namespaces) {
    }

    /** The packaged programs read, by the agent (its source: name, text, location); the last few only. */
    private static final class ParsedPrograms {
        private static final int KEPT = 16;
        private static final Map<AgentSource, Parsed> READ = new LinkedHashMap<>(32, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<AgentSource, Parsed> eldest) {
                return size() > KEPT;
            }
        };

        static synchronized Parsed get(AgentSource agent) {
            return READ.get(agent);
        }

        static synchronized void put(AgentSource agent, Parsed parsed) {
            READ.put(agent, parsed);
        }
    }
}
