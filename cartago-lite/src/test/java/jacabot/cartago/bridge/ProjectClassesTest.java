package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Users' artifacts: class path entries, sources compiled before the run, errors as one line each. */
class ProjectClassesTest {
    private static final String MAS = """
            MAS t {
                environment: jacabot.cartago.bridge.CartagoEnvironment
                agents: a agentArchClass jacabot.cartago.bridge.CAgentArch;
                %s
            }
            """;

    private static final String TALLY = """
            package my.tools;
            public class Tally extends jacabot.cartago.Artifact {
                void init() { defineObsProperty("tally", 0); }
                @jacabot.cartago.OPERATION void add(int n) {
                    getObsProperty("tally").updateValue(getObsProperty("tally").intValue() + n);
                }
            }
            """;

    private static final String AGENT = """
            !go.
            +!go <- makeArtifact("t", "my.tools.Tally", [], T); focus(T); add(4); add(5).
            +tally(9) <- println("tally 9"); .stopMAS.
            """;

    @Test
    void compiledClassesComeFromTheMas2jClasspathEntries(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("elsewhere/my/tools/Tally.java", TALLY));
        SourceCompiler.compile(List.of(dir.resolve("elsewhere/my/tools/Tally.java")), List.of(), dir.resolve("classes"));
        ProjectRun.write(dir, Map.of("t.mas2j", MAS.formatted("classpath: \"classes\";"), "a.asl", AGENT));
        ProjectRun run = ProjectRun.run(dir.resolve("t.mas2j"), 0, 90_000);
        assertEquals("[a] tally 9\n", run.output);
    }

    @Test
    void sourcesUnderSrcJavaAreCompiledBeforeTheRun(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("src/java/my/tools/Tally.java", TALLY,
                "t.mas2j", MAS.formatted(""), "a.asl", AGENT));
        ProjectRun run = ProjectRun.run(dir.resolve("t.mas2j"), 0, 90_000);
        assertEquals("[a] tally 9\n", run.output);
    }

    @Test
    void aCompileErrorIsFileLineMessage(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("Broken.java", "public class Broken {\n  void f() {\n    int x = \"no\";\n  }\n}\n",
                "t.mas2j", MAS.formatted(""), "a.asl", AGENT));
        var e = assertThrows(SourceCompiler.CompileError.class, () -> ProjectClasses.prepare(dir.resolve("t.mas2j"), List.of()));
        assertEquals(1, e.lines().size(), e.getMessage());
        assertTrue(e.lines().get(0).matches(".*Broken\\.java:3: incompatible types: .*"), e.lines().get(0));
    }

    /** Jason's own demos ship internal actions written against Jason's Java API, which does not exist here. */
    @Test
    void aSourceUsingJasonsJavaApiIsLeftOutWithAWarningAndTheRestRuns(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("src/java/my/tools/Tally.java", TALLY,
                "src/java/mylib/twice.java", "package mylib;\n\nimport jason.asSemantics.*;\nimport jason.asSyntax.*;\n"
                        + "public class twice extends DefaultInternalAction {}\n",
                "t.mas2j", MAS.formatted(""), "a.asl", AGENT));
        var cp = ProjectClasses.prepare(dir.resolve("t.mas2j"), List.of()).classpath();
        assertEquals(1, cp.sources().size(), cp.sources().toString());
        assertTrue(cp.sources().get(0).endsWith("Tally.java"), cp.sources().toString());
        assertEquals(1, cp.warnings().size(), cp.warnings().toString());
        assertTrue(cp.warnings().get(0).matches(".*twice\\.java:3: warning: imports jason\\.asSemantics\\.\\* of Jason's own Java API.*"),
                cp.warnings().get(0));
        ProjectRun run = ProjectRun.run(dir.resolve("t.mas2j"), 0, 90_000);
        assertEquals("[a] tally 9\n", run.output);
    }

    @Test
    void aMissingMas2jEntryIsAWarningAMissingCommandLineEntryAnError(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("t.mas2j", MAS.formatted("classpath: \"../../lib/cartago.jar\";"), "a.asl", AGENT));
        var cp = ProjectClasses.prepare(dir.resolve("t.mas2j"), List.of()).classpath();
        assertEquals(List.of(), cp.entries());
        assertEquals(1, cp.warnings().size());
        assertTrue(cp.warnings().get(0).endsWith("classpath entry '../../lib/cartago.jar' not found, ignored"), cp.warnings().get(0));
        var e = assertThrows(ProjectClasspath.Problem.class,
                () -> ProjectClasses.prepare(dir.resolve("t.mas2j"), List.of(dir.resolve("none.jar"))));
        assertTrue(e.getMessage().startsWith("--classpath '"), e.getMessage());
    }

    @Test
    void commandLineEntriesAndJarWildcards(@TempDir Path dir) throws Exception {
        Files.createDirectories(dir.resolve("lib"));
        Files.writeString(dir.resolve("lib/a.jar"), "");
        Files.writeString(dir.resolve("lib/b.jar"), "");
        Files.writeString(dir.resolve("lib/notes.txt"), "");
        var cp = ProjectClasspath.of(null, List.of(dir.resolve("lib/*")));
        assertEquals(List.of(dir.resolve("lib/a.jar"), dir.resolve("lib/b.jar")), cp.entries());
    }

    @Test
    void anUnknownClassFailsTheActionNotTheRun(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("t.mas2j", MAS.formatted(""), "a.asl", """
                !go.
                +!go <- makeArtifact("t", "my.tools.Missing", [], T).
                -!go[env_failure_reason(R)] <- println("failed: ", R); .stopMAS.
                """));
        ProjectRun run = ProjectRun.run(dir.resolve("t.mas2j"), 0, 90_000);
        assertEquals("[a] failed: unknown_class(\"my.tools.Missing\")\n", run.output);
    }
}
