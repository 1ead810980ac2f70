package jacabot.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.syntax.AgentProgram;
import jacabot.robot.Experiment;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The launcher's one way to load agents: packaged ones from the class path, others from disk, includes beside them. */
class AgentSourceTest {
    private static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    @Test
    void aPackagedAgentReadsItsIncludeFromTheClassPath() throws Exception {
        for (Experiment e : Experiment.values()) {
            AgentSource packaged = AgentSource.packaged(e, "agents/src/main/asl/" + e.id() + ".asl");
            AgentProgram program = packaged.parse(packaged.parser());
            assertEquals("agents/src/main/asl/skills/initial-phase.asl", program.plans().get(1).source().file(), e.id());
            // the same program as the file in the repository (run from the repository, --agent)
            AgentSource file = AgentSource.file(ROOT.resolve("agents/src/main/asl/" + e.id() + ".asl"));
            assertEquals(texts(file.parse(file.parser())), texts(program), e.id());
            // a skill may include others (delivery includes heading, recharge its two sides)
            var sources = packaged.sources();
            long includes = sources.stream().mapToLong(s -> s.text().lines().filter(l -> l.trim().startsWith("{ include(")).count()).sum();
            assertEquals(1 + includes, sources.size(), "the agent and the skills it includes");
        }
    }

    /**
     * A packaged agent is read once per process: the next fresh parser gets the same program and is
     * left as reading it itself would leave it (the fresh variables' and namespaces' numbers, the
     * functions), so runs after the first run the same program with the same numbers.
     */
    @Test
    void aPackagedAgentIsReadOnceAndItsParserLeftAsReadingItWould() throws Exception {
        for (Experiment e : Experiment.values()) {
            AgentSource packaged = AgentSource.packaged(e);
            AgentProgram first = packaged.parse(packaged.parser());
            var parser = packaged.parser();
            AgentProgram again = packaged.parse(parser);
            assertSame(first, again, e.id());
            // what a parser of its own makes of the same source, read afresh
            var own = packaged.parser();
            AgentProgram read = own.parse(packaged.source());
            assertEquals(texts(read), texts(again), e.id());
            assertTrue(own.varCounter().get() > 0, e.id());
            assertEquals(own.varCounter().get(), parser.varCounter().get(), e.id());
            assertEquals(own.namespacesNumbered(), parser.namespacesNumbered(), e.id());
            // the numbers go on from there as they would: the next fresh variable is the same
            assertEquals(own.parseTerm("p(_)").toString(), parser.parseTerm("p(_)").toString(), e.id());
        }
        // a parser that has read something reads anew
        AgentSource packaged = AgentSource.packaged(Experiment.NAVIGATION);
        var used = packaged.parser();
        used.parseTerm("p(_)");
        assertNotSame(packaged.parse(packaged.parser()), packaged.parse(used));
    }

    @Test
    void aMissingIncludeIsOneLineWithItsPlace() {
        AgentSource edited = AgentSource.packaged(Experiment.NAVIGATION).withText("a(1).\n{ include(\"common/nope.asl\") }\n");
        var e = assertThrows(AslSyntaxException.class, () -> edited.parse(edited.parser()));
        assertEquals("navigation.asl:2:1: error: included file 'common/nope.asl' not found", e.getMessage());
    }

    @Test
    void aFileIncludesFilesBesideItWhereverItIsRunFrom(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("mine/common"));
        Files.writeString(dir.resolve("mine/common/start.asl"), "+!start <- println(hello).\n");
        Files.writeString(dir.resolve("mine/agent.asl"), "!start.\n{ include(\"common/start.asl\") }\n");
        AgentSource file = AgentSource.file(dir.resolve("mine/agent.asl"));
        assertEquals(1, file.parse(file.parser()).plans().size());
        Files.delete(dir.resolve("mine/common/start.asl"));
        var e = assertThrows(AslSyntaxException.class, () -> file.parse(file.parser()));
        assertEquals(dir.resolve("mine/agent.asl") + ":2:1: error: included file 'common/start.asl' not found", e.getMessage());
    }

    /** A copy of a packaged agent, edited elsewhere, still finds the skills it includes (the installation's). */
    @Test
    void aCopiedAgentFallsBackOnThePackagedIncludes(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("my-agent.asl"), AgentSource.packaged(Experiment.NAVIGATION).text());
        AgentSource copy = AgentSource.file(dir.resolve("my-agent.asl"));
        AgentProgram program = copy.parse(copy.parser());
        assertEquals("agents/src/main/asl/skills/initial-phase.asl", program.plans().get(1).source().file());
        assertEquals(texts(AgentSource.packaged(Experiment.NAVIGATION).parse(copy.parser())), texts(program));
        // a file of its own beside it comes first
        Files.createDirectories(dir.resolve("skills"));
        Files.writeString(dir.resolve("skills/initial-phase.asl"), "+!init(Id) <- lookupArtifact(\"mine\", Id).\n");
        assertEquals(dir.resolve("skills/initial-phase.asl").toString(), copy.parse(copy.parser()).plans().get(0).source().file());
    }

    @Test
    void theAgentsCodeMetricsCountWhatTheyInclude() throws Exception {
        AgentSource packaged = AgentSource.packaged(Experiment.OBSTACLE_AVOIDANCE);
        var withInclude = AgentMetrics.of(Experiment.OBSTACLE_AVOIDANCE, packaged);
        int agentOnly = 0;
        for (String line : packaged.text().split("\n")) {
            String t = line.trim();
            if (!t.isEmpty() && !t.startsWith("//") && !t.startsWith("/*") && !t.startsWith("*")) {
                agentOnly++;
            }
        }
        int included = 0;
        for (var source : packaged.sources().subList(1, packaged.sources().size())) {
            included += (int) source.text().lines().map(String::trim)
                    .filter(t -> !t.isEmpty() && !t.startsWith("//") && !t.startsWith("/*") && !t.startsWith("*")).count();
        }
        assertEquals(agentOnly + included, withInclude.codeLines(), "the agent's code lines and its skills'");
    }

    private static List<String> texts(AgentProgram p) {
        return p.plans().stream().map(Object::toString).toList();
    }
}
