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
import java.util.List;

/**
 * An agent program as the launcher loads it: its text, the name it goes by in messages and logs,
 * and where its {@code { include("...") }} directives are read from: beside it on the class path
 * for the packaged agents ({@code /asl/NAME.asl} in the agents jar), beside it on disk for a file.
 */
public record AgentSource(SourceResolver.Source source, SourceResolver includes) {
    /** The packaged agents' folder on the class path (agents/src/main/asl in the repository). */
    private static final String PACKAGED = "asl/";

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
            return new AgentSource(new SourceResolver.Source(name, text, location), SourceResolver.resources(loader));
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

    /** {@return the program, its includes read in} */
    public AgentProgram parse(AslParser parser) throws AslSyntaxException {
        try {
            return parser.parse(source);
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
}
