package jacabot.agent.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.parser.AslParser;
import jacabot.agent.parser.AslSyntaxException;
import jacabot.agent.semantics.Clock;
import jacabot.agent.semantics.Message;
import jacabot.agent.syntax.Literal;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Messaging between agents, .mas2j projects, and the determinism of stepping mode. */
class LocalMASTest {
    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final AtomicLong now = new AtomicLong();
    private final LocalMAS mas = new LocalMAS(now::get, new PrintStream(bytes, true, StandardCharsets.UTF_8), 1);
    private final AslParser parser = new AslParser();

    private void agent(String name, String source) throws Exception {
        mas.createAgent(name, parser.parse(source, name + ".asl"), parser, null);
    }

    private List<String> lines() {
        return bytes.toString(StandardCharsets.UTF_8).lines().collect(Collectors.toList());
    }

    @Test
    void tellAchieveAndAskBetweenAgents() throws Exception {
        agent("alice", """
                !go.
                +!go <- .send(bob, tell, price(10)); .send(bob, achieve, greet(alice));
                        .send(bob, askOne, stock(S), Answer); .print("bob has ", Answer);
                        .send(bob, askOne, nothing(_), None); .print("unknown: ", None);
                        .send(bob, askAll, stock(_), All); .print(All).
                """);
        agent("bob", """
                stock(3). stock(4).
                +price(P)[source(A)] <- .print("price ", P, " from ", A).
                +!greet(W)[source(A)] <- .print("hello ", W, " (asked by ", A, ")").
                """);
        mas.runUntilQuiescent(10_000);
        assertEquals(List.of("[bob] price 10 from alice", "[bob] hello alice (asked by alice)",
                "[alice] bob has stock(3)[source(bob)]", "[alice] unknown: false",
                "[alice] [stock(3)[source(bob)],stock(4)[source(bob)]]"), lines());
    }

    /** As Jason's, whose counter is one per JVM (recorded from Jason 3.2.0: 1, 2, 3). */
    @Test
    void intentionsAreNumberedByOneCounterForTheWholeSystem() throws Exception {
        agent("a", """
                !start.
                +!start <- .intention(I, running); .print(I); .send(b, achieve, go).
                +done <- .intention(I, running); .print(I).
                """);
        agent("b", """
                +!go <- .intention(I, running); .print(I); .send(a, tell, done).
                """);
        mas.runUntilQuiescent(10_000);
        assertEquals(List.of("[a] 1", "[b] 2", "[a] 3"), lines());
    }

    /** Stepping: an agent whose cycle throws is taken out when asked to be (a team's host), else the throw ends the step. */
    @Test
    void anAgentWhoseCycleThrowsIsTakenOutAndTheOthersGoOn() throws Exception {
        String counter = "n(0).\n!count.\n+!count : n(N) & N < 5 <- -+n(N + 1); .print(N); !count.\n+!count.\n";
        for (boolean listening : new boolean[] {false, true}) {
            var out = new ByteArrayOutputStream();
            var system = new LocalMAS(now::get, new PrintStream(out, true, StandardCharsets.UTF_8), 1);
            system.createAgent("alice", parser.parse(counter, "alice.asl"), parser, null);
            system.createAgent("bob", parser.parse(counter, "bob.asl"), parser, null);
            system.agent("bob").setPlanListener((event, plan) -> {
                throw new IllegalStateException("simulated");
            });
            if (!listening) {
                var thrown = assertThrows(IllegalStateException.class, () -> system.runUntilQuiescent(10_000));
                assertEquals("simulated", thrown.getMessage());
                continue;
            }
            List<String> died = new ArrayList<>();
            system.onAgentDied((name, e) -> died.add(name + ": " + e.getMessage()));
            system.runUntilQuiescent(10_000);
            assertEquals(List.of("bob: simulated"), died);
            assertEquals(null, system.agent("bob"), "out of the system");
            assertEquals(List.of("alice"), system.agentNames());
            assertEquals(List.of("[alice] 0", "[alice] 1", "[alice] 2", "[alice] 3", "[alice] 4"),
                    out.toString(StandardCharsets.UTF_8).lines().toList(), "alice went on");
        }
    }

    /** What Jason 3.2.0 prints for these three agents (in some order): every other agent gets both messages. */
    @Test
    void broadcastReachesEveryOtherAgent() throws Exception {
        agent("alice", "!go.\n+!go <- .broadcast(tell, hello(1)); .broadcast(achieve, greet).\n"
                + "+hello(X)[source(A)] <- .print(hello, X, A).\n");
        String listener = "+hello(X)[source(A)] <- .print(hello, X, A).\n+!greet[source(A)] <- .print(greet, A).\n";
        agent("bob", listener);
        agent("carol", listener);
        mas.runUntilQuiescent(10_000);
        var got = new ArrayList<>(lines());
        Collections.sort(got);
        assertEquals(List.of("[bob] greetalice", "[bob] hello1alice", "[carol] greetalice", "[carol] hello1alice"), got);
    }

    @Test
    void unnamedPlansAreNumberedAcrossAgentsInLoadOrder() throws Exception {
        // Jason 3.2 numbers p__N JVM-wide: a's two plans are p__1 and p__2, so b's go on from p__3
        agent("a", "+!x <- true.\n+!y <- true.\n");
        agent("b", "!s.\n+!z <- true.\n+!s <- .relevant_plans({+!_}, _, L); .print(L).\n");
        mas.runUntilQuiescent(10_000);
        assertEquals(List.of("[b] [p__3[source(self),url(\"file:b.asl\")],p__4[source(self),url(\"file:b.asl\")]]"), lines());
    }

    @Test
    void messagesFromOneSenderArriveInOrder() throws Exception {
        agent("a", "!go.\n+!go <- for (.range(I, 1, 20)) { .send(b, tell, n(I)) }.\n");
        agent("b", "+n(I) <- .print(I).\n");
        mas.runUntilQuiescent(100_000);
        List<String> expected = new ArrayList<>();
        for (int i = 1; i <= 20; i++) {
            expected.add("[b] " + i);
        }
        assertEquals(expected, lines());
    }

    @Test
    void steppingModeIsDeterministicUnderASeed() throws Exception {
        String program = """
                !a. !b.
                +!a <- for (.range(I, 1, 5)) { .random(R); .print(a, I, " ", R) }.
                +!b <- for (.range(I, 1, 5)) { .wait(10); .print(b, I) }.
                """;
        List<String> first = runStepped(program);
        List<String> second = runStepped(program);
        assertEquals(first, second);
        assertEquals(10, first.size());
    }

    private static List<String> runStepped(String program) throws Exception {
        var bytes = new ByteArrayOutputStream();
        var now = new AtomicLong();
        var mas = new LocalMAS(now::get, new PrintStream(bytes, true, StandardCharsets.UTF_8), 99);
        var parser = new AslParser();
        mas.createAgent("x", parser.parse(program, "x.asl"), parser, null);
        for (int step = 0; step < 100; step++) {
            mas.runUntilQuiescent(1000);
            now.addAndGet(5);
        }
        return bytes.toString(StandardCharsets.UTF_8).lines().collect(Collectors.toList());
    }

    @Test
    void mas2jProjectsCreateNumberedAgents(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("w.asl"), "!hi.\n+!hi <- .my_name(N); .print(N).\n");
        Files.writeString(dir.resolve("p.mas2j"), """
                MAS demo {
                    infrastructure: Local
                    agents: w #3; solo w.asl [verbose=1];
                }
                """);
        var project = Mas2jReader.read(dir.resolve("p.mas2j"));
        assertEquals("demo", project.name());
        assertEquals(3, project.agents().get(0).instances());
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("p.mas2j"));
        assertEquals(List.of("w1", "w2", "w3", "solo"), launched.agentNames());
        launched.runUntilQuiescent(1000);
        assertTrue(lines().containsAll(List.of("[w1] w1", "[w2] w2", "[w3] w3", "[solo] solo")), lines().toString());
    }

    /**
     * A name given twice is Jason 3.2.0's next free one, NAME_1, NAME_2, ... (its RuntimeServices'
     * getNewAgentName), for a project's agents and for .create_agent of a name an agent has: Jason
     * printed these names for `agents: a; a; a #2; a; c;`, and c's .create_agent(a, ...) succeeds (a_3).
     */
    @Test
    void aNameGivenTwiceIsJasonsNextFreeOne(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("a.asl"), "!hi.\n+!hi <- .my_name(N); .print(N).\n");
        Files.writeString(dir.resolve("c.asl"), "!go.\n+!go <- .create_agent(a, \"a.asl\"); .print(created); "
                + ".create_agent(Xy, \"a.asl\"); .string(Xy); .print(Xy, \" a string\").\n");
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n agents: a; a; a #2; a; c;\n}\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("p.mas2j"));
        assertEquals(List.of("a", "a_1", "a1", "a2", "a_2", "c"), launched.agentNames());
        launched.runUntilQuiescent(1000);
        // a variable: Jason names the agent after it, its first letter in lower case, and binds it to that name as a string
        assertTrue(lines().containsAll(List.of("[a_1] a_1", "[c] created", "[c] xy a string")), lines().toString());
        assertEquals(List.of("a", "a_1", "a1", "a2", "a_2", "c", "a_3", "xy"), launched.agentNames());
    }

    /**
     * Fresh variables of all agents come from one counter, as Jason's: each agent's own unnamed
     * variables (each instance reads its source) and Jason's 18 in kqmlPlans.asl take numbers first
     * (18 for a, 2 + 18 for each b), then .relevant_plans' source(_) and the plan's renaming.
     * Jason 3.2.0 prints the same line.
     */
    @Test
    void freshVariablesAreNumberedAcrossAgentsAsJasonsAre(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("a.asl"), "!s.\n+!s <- .send(b2, tell, v(1)).\n");
        Files.writeString(dir.resolve("b.asl"), """
                x(_).
                +v(X)[source(S)] <- .relevant_plans({+!h(_)}, L); .print(L).
                +!h(A) <- .print(A).
                """);
        Files.writeString(dir.resolve("two.mas2j"), "MAS two { agents: a; b #2; }");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("two.mas2j"));
        launched.runUntilQuiescent(1000);
        assertEquals(List.of("[b2] [{ @p__5[source(self),url(\"file:b.asl\")] +!h(_60) <- .print(_60) }]"), lines());
    }

    /** Options beliefs= and goals=, a file named without .asl, and the host after #N (Jason 3.2.0 prints the same lines). */
    @Test
    void mas2jAgentOptionsAddBeliefsAndGoals(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("ag.asl"), "+!g : b(X) <- .print(X, \" \", c).\n!h.\n+!h : b(Y) <- .print(h, Y).\n");
        Files.writeString(dir.resolve("p.mas2j"), """
                MAS m {
                    infrastructure: Local
                    agents: ag [beliefs="b(1), c", goals="g"] #2; other ag at "localhost" #1;
                }
                """);
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("p.mas2j"));
        launched.runUntilQuiescent(1000);
        var got = new ArrayList<>(lines());
        assertEquals(List.of("[ag1] 1 c", "[ag1] h1"), got.stream().filter(l -> l.startsWith("[ag1]")).collect(Collectors.toList()));
        assertTrue(got.contains("[ag2] 1 c") && got.contains("[ag2] h1"), got.toString());
        assertTrue(got.stream().noneMatch(l -> l.startsWith("[other] 1")), "other has no option beliefs: " + got);
    }

    /** An option that does not read is told with the project and the agent, not as a nameless {@code <term>:1:3}. */
    @Test
    void anOptionThatDoesNotReadNamesTheProjectAndTheAgent(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("ag.asl"), "!g.\n+!g <- .stopMAS.\n");
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n agents: ag [beliefs=\"b(1), c(\"];\n}\n");
        var launcher = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true);
        var e = assertThrows(MasLauncher.UserError.class, () -> launcher.load(dir.resolve("p.mas2j")));
        assertTrue(e.getMessage().startsWith(dir.resolve("p.mas2j") + ": agent ag's beliefs \"b(1), c(\": "), e.getMessage());
        assertFalse(e.getMessage().contains("<term>") || e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().endsWith("expected ')' before the option's end: the '(' at column 8 is not closed"), e.getMessage());
    }

    /** A folder given as the project names the projects in it. */
    @Test
    void aFolderNamesItsProjects(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("b.mas2j"), "MAS b {\n agents: a;\n}\n");
        Files.writeString(dir.resolve("a.jcm"), "mas a {\n agent a\n}\n");
        var launcher = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true);
        var e = assertThrows(MasLauncher.UserError.class, () -> launcher.load(dir));
        assertEquals(dir + ": a folder, not a project: run " + dir.resolve("a.jcm") + " or " + dir.resolve("b.mas2j"), e.getMessage());
    }

    /** A source a project names that is nowhere is told with the project and where it was looked for. */
    @Test
    void aMissingSourceNamesTheProjectAndTheFolders(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n agents: nobody;\n}\n");
        var launcher = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true);
        var e = assertThrows(MasLauncher.UserError.class, () -> launcher.load(dir.resolve("p.mas2j")));
        assertEquals(dir.resolve("p.mas2j") + ": agent source 'nobody.asl' not found (looked in " + dir + ")", e.getMessage());
    }

    /** CArtAgO's remote examples give the environment a structure: it reaches the class as its text. */
    @Test
    void environmentArgumentsMayBeStructures(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"),
                "MAS m {\n environment: my.Env(\"standalone\", protocol(lipermi), 3, -1)\n agents: a;\n}\n");
        var project = Mas2jReader.read(dir.resolve("p.mas2j"));
        assertEquals(List.of("standalone", "protocol(lipermi)", "3", "-1"), project.environmentArgs());
    }

    /** A project's syntax errors are said as an agent's are, not with ANTLR's token sets. */
    @Test
    void aProjectsSyntaxErrorIsSaidInOurWords(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n agents: a beliefs=\"x\";\n}\n");
        var e = assertThrows(AslSyntaxException.class, () -> Mas2jReader.read(dir.resolve("p.mas2j")));
        assertTrue(e.getMessage().startsWith(dir.resolve("p.mas2j") + ":2:19: error: unexpected '=', expected "), e.getMessage());
        assertFalse(e.getMessage().contains("expecting") || e.getMessage().contains("{"), e.getMessage());
    }

    @Test
    void anInfrastructureOtherThanLocalIsRefused(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n infrastructure: Jade\n agents: a;\n}\n");
        var e = assertThrows(AslSyntaxException.class,
                () -> Mas2jReader.read(dir.resolve("p.mas2j")));
        assertTrue(e.getMessage().contains("infrastructure 'Jade' is not supported"), e.getMessage());
    }

    /** Jason refuses {@code at} as an agent name and prints this console line; we do too, and stop with an error. */
    @Test
    void aProjectThatDoesNotParsePrintsJasonsLine(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("p.mas2j"), "MAS m {\n agents: a; at;\n}\n");
        var launcher = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true);
        assertThrows(MasLauncher.UserError.class, () -> launcher.load(dir.resolve("p.mas2j")));
        assertEquals(List.of("[RunLocalMAS] Error parsing file file:" + dir.resolve("p.mas2j") + "!"), lines());
    }

    /** The directory facilitator: Jason 3.2.0 prints these lines for this project. */
    @Test
    void theDirectoryFacilitatorRegistersSearchesAndTellsSubscribers(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("s.asl"), "!reg.\n+!reg <- .df_register(seller); .df_register(\"buyer\"); .df_deregister(buyer).\n");
        Files.writeString(dir.resolve("c.asl"), """
                !go.
                +!go <- .df_subscribe(seller); .wait(200); .df_search(seller, L); .print(L); .df_search(buyer, B); .print(B);
                        .findall(P, provider(P, S), Ps); .sort(Ps, Sorted); .print(Sorted); .stopMAS.
                +provider(P, S)[source(A)] <- .print(told(S), " by ", A).
                """);
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: s #2; c; }\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("p.mas2j"));
        runFor20s(launched, true);
        assertTrue(launched.isStopped(), "the project reaches .stopMAS");
        assertEquals(List.of("[c] told(\"seller\") by df", "[c] told(\"seller\") by df", "[c] [s1,s2]", "[c] []", "[c] [s1,s2]"), lines());
    }

    /** With verbose=0 Jason's .print writes the bare text; warnings keep the agent's name (as Jason 3.2.0). */
    @Test
    void verboseZeroPrintsBareText(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("q.asl"), "!s.\n+!s <- .print(hello, 1); .println(x); !nope.\n");
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: q [verbose=0]; }\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, true).load(dir.resolve("p.mas2j"));
        launched.runUntilQuiescent(1000);
        // Jason 3.2.0's lines for the failure, its dump of the intention included (its .print at
        // verbose 0 also leaves the line open: "hello1x"; ours ends it)
        assertEquals(List.of("hello1", "x", "[q] No fail event was generated for +!nope[source(self)]", "[q] ",
                "intention 1: ", "    +!s[source(self)] <- ... !nope / {}", "",
                "[q] Found a goal for which there is no relevant plan: +!nope[source(self)]"), lines());
    }

    /**
     * Jason's idle events and shutdown: {@code +jag_sleeping}/{@code +jag_awaking}, a
     * {@code signal} (an event, no belief) and {@code .stopMAS(T)} with {@code +jag_shutting_down(T)};
     * the lines of each agent as Jason 3.2.0 printed them (up to the shutdown).
     */
    @Test
    void idleEventsSignalAndStopWithDeadline(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("idle.asl"), """
                +hi(X)[source(A)] <- .print(hi(X), " from ", A, " believed: ", .count(hi(_))).
                +jag_sleeping <- .print(sleeping).
                +jag_awaking <- .print(awaking).
                +jag_shutting_down(T) <- .print(shutting_down(T)).
                """);
        Files.writeString(dir.resolve("s.asl"), """
                !go.
                +!go <- .wait(300); .send(idle, signal, hi(1)); .wait(300); .stopMAS(400).
                +jag_shutting_down(T) <- .print(bye(T)).
                """);
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: idle; s; }\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, false).load(dir.resolve("p.mas2j"));
        runFor20s(launched, false);
        assertTrue(launched.isStopped(), "the project stops after the deadline");
        var idle = lines().stream().filter(l -> l.startsWith("[idle]")).collect(Collectors.toList());
        assertEquals(List.of("[idle] sleeping", "[idle] awaking", "[idle] hi(1) from s believed: 0", "[idle] sleeping",
                "[idle] shutting_down(400)", "[idle] awaking"), idle.subList(0, Math.min(6, idle.size())));
        assertTrue(lines().contains("[s] bye(400)"), lines().toString());
    }

    /** .create_agent, tellHow (a plan as text, plan terms in a list) and .kill_agent: the lines Jason 3.2.0 printed. */
    @Test
    void agentsCreatedToldPlansAndKilled(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("boss.asl"), """
                !go.
                +!go <- .create_agent(w, "worker.asl"); .wait(200);
                        .send(w, tellHow, "+!hello(X)[source(A)] <- .print(hello(X), \\" from \\", A).");
                        .send(w, tellHow, [{ @k +!bye <- .print(bye) }]);
                        .wait(100); .send(w, achieve, hello(1)); .send(w, achieve, bye); .wait(200);
                        .all_names(L1); .print(L1);
                        .kill_agent(w); .wait(100);
                        .all_names(L2); .print(L2);
                        .stopMAS.
                """);
        Files.writeString(dir.resolve("worker.asl"), "!start.\n+!start <- .print(started).\n");
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: boss; }\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, false).load(dir.resolve("p.mas2j"));
        runFor20s(launched, false);
        assertTrue(launched.isStopped(), "the project reaches .stopMAS");
        assertEquals(List.of("[w] started", "[w] hello(1) from boss", "[w] bye", "[boss] [boss,w]", "[boss] [boss]"), lines());
    }

    /** .clone: the copy has the beliefs and plans, without their events or the goals (Jason 3.2.0's lines). */
    @Test
    void aCloneHasTheBeliefsAndPlansButNoEvents(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("main.asl"), """
                test(1).
                !start.
                +!start <- +a(40); .clone("bob"); .send(bob, tell, p(10)); .wait(300); .stopMAS.
                +a(X) <- .my_name(N); .print(added(X), " in ", N).
                +p(X)[source(S)] : a(V) & test(T) <- .print(X, " : ", V + T, " from ", S).
                """);
        Files.writeString(dir.resolve("p.mas2j"), "MAS p { agents: main; }\n");
        var launched = new MasLauncher(new PrintStream(bytes, true, StandardCharsets.UTF_8), 0, false).load(dir.resolve("p.mas2j"));
        runFor20s(launched, false);
        assertTrue(launched.isStopped(), "the project reaches .stopMAS");
        assertEquals(List.of("[main] added(40) in main", "[bob] 10 : 41 from main"), lines());
    }

    /** An agent with nothing to do parks its thread after its yields, and a message still wakes it. */
    @Test
    void anIdleAgentParksAndAMessageWakesIt() throws Exception {
        var threaded = new LocalMAS(Clock.wall(), new PrintStream(bytes, true, StandardCharsets.UTF_8), 1);
        threaded.createAgent("bob", parser.parse("+hello[source(A)] <- .print(hello, A); .stopMAS.\n", "bob.asl"), parser, null);
        Thread runner = startRunning(threaded, false);
        Thread bob = null;
        for (long end = System.nanoTime() + 10_000_000_000L; System.nanoTime() < end; Thread.sleep(5)) {
            bob = Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().equals("agent-bob")).findFirst().orElse(null);
            if (bob != null && bob.getState() == Thread.State.TIMED_WAITING) {
                break;
            }
        }
        assertTrue(bob != null && bob.getState() == Thread.State.TIMED_WAITING, "the idle agent's thread parks, it does not spin");
        threaded.deliver(new Message("m1", "alice", "bob", "tell", Literal.atom("hello"), null));
        runner.join(10_000);
        assertTrue(threaded.isStopped(), "the message woke bob, whose plan stopped the system");
        assertEquals(List.of("[bob] helloalice"), lines());
    }

    /** A receiver lingering between the messages of a stream (threads, not stepping) loses none, in order. */
    @Test
    void aStreamOfMessagesArrivesWholeAndInOrderBetweenThreads() throws Exception {
        var threaded = new LocalMAS(Clock.wall(), new PrintStream(bytes, true, StandardCharsets.UTF_8), 1);
        threaded.createAgent("a", parser.parse("!go.\n+!go <- for (.range(I, 1, 5000)) { .send(b, tell, n(I)) }; .send(b, tell, last).\n", "a.asl"),
                parser, null);
        threaded.createAgent("b", parser.parse("next(1).\n+n(I) : next(I) <- -+next(I + 1).\n+n(I) <- .print(out_of_order, I).\n"
                + "+last : next(N) <- .print(got, N - 1); .stopMAS.\n", "b.asl"), parser, null);
        runFor20s(threaded, false);
        assertEquals(List.of("[b] got5000"), lines());
    }

    /** Runs the project on a daemon thread, stepping or a thread per agent, for at most 20 s (its .stopMAS ends it sooner). */
    private static void runFor20s(LocalMAS launched, boolean stepping) throws InterruptedException {
        startRunning(launched, stepping).join(20_000);
    }

    /** Starts the project on a daemon thread, stepping or a thread per agent. */
    private static Thread startRunning(LocalMAS launched, boolean stepping) {
        Thread runner = new Thread(() -> {
            try {
                if (stepping) {
                    launched.runStepping();
                } else {
                    launched.runThreads();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        runner.setDaemon(true);
        runner.start();
        return runner;
    }
}
