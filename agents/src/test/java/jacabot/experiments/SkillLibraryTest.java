package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.SourceResolver;
import jacabot.agent.syntax.AgentProgram;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.Plan;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The default agents are skills composed by include (Chapter 5 §2: a new skill is "new plans and/or
 * beliefs"): no plan is written in two files, no tuning constant is declared in two files (nor one
 * parameter in two skills), every plan carries a label that says what it does, and no agent has two
 * plans of one label. The agents as published (as-published/) are the thesis' listings and are exempt.
 */
class SkillLibraryTest {
    private static final Path ASL = Path.of(System.getProperty("jacabot.projectDir", ".")).resolve("src/main/asl");

    /** {@return every default agent file and skill file, each parsed on its own (without its includes)} */
    private static Map<Path, AgentProgram> library() throws Exception {
        var out = new TreeMap<Path, AgentProgram>();
        try (Stream<Path> files = Files.walk(ASL)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".asl") && !ASL.relativize(p).startsWith("as-published")).toList()) {
                out.put(ASL.relativize(f), new AslParser(SkillLibraryTest::noIncludes).parseFile(f));
            }
        }
        return out;
    }

    private static SourceResolver.Source noIncludes(String file,
            SourceResolver.Source from) {
        return new SourceResolver.Source(file, "", null);
    }

    /** A plan without its label: what two files would share if one copied the other. */
    private static String text(Plan p) {
        return p.trigger() + " : " + p.context() + " <- " + p.body();
    }

    @Test
    void noPlanIsWrittenInTwoFiles() throws Exception {
        var where = new TreeMap<String, Set<String>>();
        library().forEach((file, program) -> program.plans().forEach(
                p -> where.computeIfAbsent(text(p), k -> new TreeSet<>()).add(file.toString())));
        var copies = where.entrySet().stream().filter(e -> e.getValue().size() > 1).map(e -> e.getValue() + " " + e.getKey()).toList();
        assertEquals(List.of(), copies, "plans written in two files: include the skill that holds them");
    }

    /** A tuning constant: a fact with a number among its arguments, e.g. avoidTimeout(3000) or quickTurnAt(50, 15). */
    private static final String CONSTANT = "[^(]*\\((.*[(,\\[])?\\s*-?[0-9].*";

    @Test
    void theConstantPatternSeesEveryArgument() {
        assertTrue("avoidTimeout(3000)".matches(CONSTANT));
        assertTrue("quickTurnAt(50,15)".matches(CONSTANT));
        assertTrue("lookAt([1,-2])".matches(CONSTANT));
        assertTrue(!"middlewareClass(\"x\")".matches(CONSTANT) && !"setUpGoal(setUpSweep)".matches(CONSTANT));
    }

    @Test
    void noConstantIsDeclaredInTwoFiles() throws Exception {
        var where = new TreeMap<String, Set<String>>();
        library().forEach((file, program) -> program.beliefs().stream()
                .filter(b -> b instanceof Literal l && l.toString().matches(CONSTANT))
                .forEach(b -> where.computeIfAbsent(b.toString(), k -> new TreeSet<>()).add(file.toString())));
        var copies = where.entrySet().stream().filter(e -> e.getValue().size() > 1).map(e -> e.getValue() + " " + e.getKey()).toList();
        assertEquals(List.of(), copies, "beliefs declared in two files: declare them once, in the skill that reads them");
    }

    /** Two skills declaring one parameter, even with two values, give an agent that includes both two beliefs of it. */
    @Test
    void noParameterIsDeclaredInTwoSkills() throws Exception {
        var where = new TreeMap<String, Set<String>>();
        library().forEach((file, program) -> {
            if (file.startsWith("skills")) {
                program.beliefs().stream().filter(b -> b instanceof Literal l && l.toString().matches(CONSTANT))
                        .forEach(b -> where.computeIfAbsent(((Literal) b).functor() + "/" + ((Literal) b).arity(), k -> new TreeSet<>())
                                .add(file.toString()));
            }
        });
        var twice = where.entrySet().stream().filter(e -> e.getValue().size() > 1).map(e -> e.getValue() + " " + e.getKey()).toList();
        assertEquals(List.of(), twice, "parameters declared in two skills: one skill holds it, the others read it");
    }

    @Test
    void everyPlanHasALabelThatSaysWhatItDoes() throws Exception {
        var unlabelled = new ArrayList<String>();
        library().forEach((file, program) -> program.plans().stream()
                .filter(p -> p.label() == null || p.label().functor().startsWith("p__"))
                .forEach(p -> unlabelled.add(file + ":" + p.source().line() + " " + p.trigger())));
        assertEquals(List.of(), unlabelled, "plans without a label");
    }

    /** The module's README is where a user looks a skill up: a skill file without its row is one they miss. */
    @Test
    void everySkillFileHasItsRowInTheReadme() throws Exception {
        String readme = Files.readString(ASL.resolve("../../../README.md").normalize());
        var missing = new TreeSet<String>();
        try (Stream<Path> files = Files.list(ASL.resolve("skills"))) {
            files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".asl"))
                    .filter(n -> !readme.contains("| `" + n + "` |")).forEach(missing::add);
        }
        assertEquals(Set.of(), missing, "skill files without a row in agents/README.md's skills table");
    }

    /** Within one agent (its includes read in), a label names one plan, and every include is found. */
    @Test
    void everyAgentNamesEachPlanOnce() throws Exception {
        for (String agent : List.of("obstacle-avoidance", "object-picking", "navigation", "suspend-resume", "tidy-up",
                "suspend-resume-task", "suspend-resume-energy", "team-delivery")) {
            Path file = ASL.resolve(agent + ".asl");
            if (!Files.exists(file)) {
                continue;
            }
            AgentProgram program = new AslParser().parseFile(file);
            var seen = new TreeSet<String>();
            var twice = program.plans().stream().map(p -> p.label().functor()).filter(l -> !seen.add(l)).toList();
            assertEquals(List.of(), twice, agent + ": labels used twice");
            assertTrue(program.plans().stream().anyMatch(p -> p.source().file().contains("skills/")), agent + " includes its skills");
        }
    }
}
