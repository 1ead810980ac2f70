package jacabot.cartago.bridge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.runtime.MasLauncher;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * JaCaMo project files ({@code .jcm}, {@link JcmReader}): the examples' .jcm versions print what
 * their .mas2j versions print; workspaces, artifacts, focus, join, beliefs, goals and instances;
 * what is not supported is refused with file:line:col.
 */
class JcmProjectTest {
    private static Path examples(String folder) {
        return Path.of(System.getProperty("jacabot.rootDir", ".."), "examples", folder);
    }

    private static List<String> lines(Path project) throws Exception {
        ProjectRun run = ProjectRun.run(project, 0, 90_000);
        assertTrue(run.stopped, project + " did not end with .stopMAS:\n" + run.output);
        return run.lines();
    }

    private static List<String> sortedWith(List<String> lines, String part) {
        return lines.stream().filter(l -> l.contains(part)).sorted().toList();
    }

    @Test
    void theCounterExampleRunsFromItsJcmAsFromItsMas2j() throws Exception {
        List<String> mas2j = lines(examples("counter").resolve("counter.mas2j"));
        List<String> jcm = lines(examples("counter").resolve("counter.jcm"));
        List<String> values = List.of("[counter_user] observed new value: 0", "[counter_user] observed new value: 1",
                "[counter_user] observed new value: 2", "[counter_user] observed new value: 3");
        assertEquals(values, sortedWith(mas2j, "observed"), mas2j.toString());
        assertEquals(values, sortedWith(jcm, "observed"), jcm.toString());
        // the third tick races .stopMAS, in both
        assertTrue(sortedWith(jcm, "perceived a tick").size() >= 2, jcm.toString());
    }

    @Test
    void theObserveExampleRunsFromItsJcmAsFromItsMas2j() throws Exception {
        for (String file : List.of("observe.mas2j", "observe.jcm")) {
            List<String> lines = lines(examples("jaca/01-observe").resolve(file));
            assertEquals(List.of("[watcher] observed count 0", "[watcher] observed count 1", "[watcher] observed count 2"),
                    sortedWith(lines, "observed"), file + ": " + lines);
            assertEquals(2, sortedWith(lines, "perceived a tick").size(), file + ": " + lines);
            assertEquals(5, lines.size(), file + ": " + lines);
        }
    }

    @Test
    void extThreadsMeterIsMadeByTheProjectAndFocusedByTheReader() throws Exception {
        for (String file : List.of("ext_thread.mas2j", "ext_thread.jcm")) {
            List<String> lines = lines(examples("jaca/ext-thread").resolve(file));
            assertEquals(1, lines.size(), file + ": " + lines);
            assertTrue(lines.get(0).matches("\\[reader\\] bumped to 11[3-9]|\\[reader\\] bumped to 1[2-9]\\d"), lines.get(0));
        }
    }

    @Test
    void agentsGetBeliefsGoalsInstancesWorkspacesAndFocus(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("p.jcm", """
                /* agents, workspaces, artifacts */
                mas p {
                    agent bob : user.asl {
                        beliefs: step(2),
                                 limit(7)     // continued after the comma
                        goals: report
                        focus: tools.c
                        instances: 2
                    }
                    agent carol : watcher.asl {
                        join: tools
                    }
                    workspace tools {
                        artifact c: jacabot.cartago.examples.BoundedCounter(7)
                    }
                }
                """, "user.asl", """
                +!report : step(S) & limit(L) & count(N) & .my_name(Me)
                    <- .print(Me, " sees ", N, " step ", S, " limit ", L); .send(carol, tell, reported(Me)).
                """, "watcher.asl", """
                !look.
                +!look <- lookupArtifact("c", C); .print("found c in tools"); +looked; !finish.
                +reported(_) <- !finish.
                // stops once it has looked and both bobs reported, in whatever order they come
                +!finish : looked & .count(reported(_), 2) <- .stopMAS.
                +!finish.
                """));
        List<String> lines = ProjectRun.run(dir.resolve("p.jcm"), 0, 60_000).lines();
        assertEquals(List.of("[bob1] bob1 sees 0 step 2 limit 7", "[bob2] bob2 sees 0 step 2 limit 7", "[carol] found c in tools"),
                lines.stream().sorted().toList(), lines.toString());
    }

    /**
     * A {@code focus:} on an artifact the project does not make: as in JaCaMo, the agent waits a
     * little for another agent to make it (five tries, 200 ms apart), and focuses on it once made;
     * never made, one line says so with the entry's place in the .jcm and the agent goes on.
     */
    @Test
    void aFocusOnAnArtifactMadeAtRunTimeWaitsForItOrSaysWhereItWasAskedFor(@TempDir Path dir) throws Exception {
        ProjectRun.write(dir, Map.of("p.jcm", """
                mas p {
                    agent bob {
                        focus: w.c
                    }
                    agent maker
                    workspace w
                }
                """, "bob.asl", """
                +count(N) <- .print("sees ", N); .stopMAS.
                """, "maker.asl", """
                !make.
                +!make <- .wait(300); joinWorkspace("w", _); makeArtifact("c", "jacabot.cartago.examples.Counter", [], _).
                """, "n.jcm", """
                mas n {
                    agent carol {
                        focus: w.c,
                               w.d
                    }
                    workspace w {
                        artifact d: jacabot.cartago.examples.Counter
                    }
                }
                """, "carol.asl", """
                !go.
                +!go <- .wait(1500); .print("goes on"); ?count(N); .print("sees ", N); .stopMAS.
                """));
        assertEquals(List.of("[bob] sees 0"), ProjectRun.run(dir.resolve("p.jcm"), 0, 60_000).lines());
        assertEquals(List.of("[carol] " + dir.resolve("n.jcm") + ":3:16: error: focus 'w.c': no artifact 'c' in workspace 'w' "
                + "(none made it in 5 tries, 1 s)", "[carol] goes on", "[carol] sees 0"),
                ProjectRun.run(dir.resolve("n.jcm"), 0, 60_000).lines());
    }

    @Test
    void organisationsAndUnknownEntriesAreRefusedWithTheirPlace(@TempDir Path dir) throws Exception {
        assertEquals(dir.resolve("o.jcm") + ":3:5: error: organisations (Moise) are not supported: jacabot runs the agents "
                + "and the environment of a .jcm", loadError(dir, "o.jcm", "mas o {\n    agent a\n    organisation org : org.xml\n}\n"));
        assertEquals(dir.resolve("r.jcm") + ":2:15: error: roles need an organisation, which is not supported "
                + "(beliefs, goals, focus, join, instances, ag-arch)", loadError(dir, "r.jcm", "mas r {\n    agent a { roles: x }\n}\n"));
        assertEquals(dir.resolve("u.jcm") + ":2:5: error: 'platform' is not supported in a .jcm here (agent, workspace, "
                + "class-path, asl-path)", loadError(dir, "u.jcm", "mas u {\n    platform: cartago()\n}\n"));
        assertEquals(dir.resolve("f.jcm") + ":2:15: error: focus 'c' is not workspace.artifact",
                loadError(dir, "f.jcm", "mas f {\n    agent a { focus: c }\n}\n"));
        assertEquals(dir.resolve("w.jcm") + ":2:30: error: focus 'tool.c': no workspace 'tool' is declared (declared: main, tools)",
                loadError(dir, "w.jcm", "mas w {\n    agent a { focus: main.x, tool.c }\n    workspace tools {\n    }\n}\n"));
        assertEquals(dir.resolve("j.jcm") + ":2:27: error: join 'nowhere': no workspace 'nowhere' is declared (declared: main)",
                loadError(dir, "j.jcm", "mas j {\n    agent a { join: main, nowhere }\n}\n"));
        assertEquals(dir.resolve("b.jcm") + ":2:1: error: expected '}' before the end of the file",
                loadError(dir, "b.jcm", "mas b {\n"));
        // beliefs: and goals: that do not read are told where they are written, as every other entry
        Files.writeString(dir.resolve("a.asl"), "!g.\n+!g.\n");
        assertEquals(dir.resolve("bel.jcm") + ":3:9: error: agent a's beliefs \"x(\": expected ')' before the option's end: "
                + "the '(' at column 2 is not closed", loadError(dir, "bel.jcm", "mas bel {\n    agent a {\n        beliefs: x(\n    }\n}\n"));
        assertEquals(dir.resolve("goal.jcm") + ":2:15: error: agent a's goals \"1\": '1' is not a literal in the option '1'",
                loadError(dir, "goal.jcm", "mas goal {\n    agent a { goals: 1 }\n}\n"));
        // a ')' too many is the option's text, told as such, not dropped
        assertEquals(dir.resolve("par.jcm") + ":2:15: error: agent a's beliefs \"x)\": unexpected ')', expected ',' or the option's end",
                loadError(dir, "par.jcm", "mas par {\n    agent a { beliefs: x) }\n}\n"));
        String missing = loadError(dir, "m.jcm", "mas m {\n    workspace w {\n        artifact c: no.Such(1)\n    }\n}\n");
        assertTrue(missing.startsWith(dir.resolve("m.jcm") + ":3:9: error: cannot make the artifact c: "), missing);
    }

    private static String loadError(Path dir, String name, String text) throws Exception {
        Files.writeString(dir.resolve(name), text);
        var out = new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8);
        return assertThrows(MasLauncher.UserError.class, () -> new MasLauncher(out, 0, false).load(dir.resolve(name))).getMessage();
    }
}
