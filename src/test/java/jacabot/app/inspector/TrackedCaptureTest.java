package jacabot.app.inspector;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.Agent;
import jacabot.agent.testing.TestAgent;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The probe prints only what changed since its last capture (agent-core's README, "How the
 * interpreter is fast"): each capture equals the mind printed anew, on a real run and cycle by
 * cycle through loops, object terms and waits; what did not change is the same object.
 */
class TrackedCaptureTest {
    static final Path ROOT = Path.of(System.getProperty("jacabot.rootDir", "."));

    private static void assertPrintedAnew(MindState m, Agent agent, String where) {
        assertEquals(MindPrintedAnew.beliefs(agent), m.beliefs(), "beliefs " + where);
        assertEquals(MindPrintedAnew.events(agent), m.events(), "events " + where);
        assertEquals(MindPrintedAnew.intentions(agent), m.intentions(), "intentions " + where);
    }

    @Test
    void aRealRunsCapturesEqualTheMindPrintedAnew() throws Exception {
        Experiment x = Experiment.parse("suspend-resume").orElseThrow();
        var run = new LockstepRun(SimWorld.of(WorldFileReader.read(ROOT.resolve(x.worldFile()))), null, x,
                AgentSource.packaged(x), 13, new PrintStream(OutputStream.nullOutputStream()));
        Agent agent = run.mas().agent(run.agentNames().get(0));
        MindProbe probe = MindProbe.attach(agent);
        var captures = new ArrayList<MindState>();
        run.onCommands((data, commands) -> {
            MindState m = probe.capture();
            assertPrintedAnew(m, agent, "at " + data.simTimeMs() + " ms");
            captures.add(m);
        });
        run.runFor(20);
        assertTrue(captures.size() >= 400, captures.size() + " steps");
        int sameIntentions = 0;
        int sameMeans = 0;
        int means = 0;
        for (int i = 1; i < captures.size(); i++) {
            MindState before = captures.get(i - 1);
            MindState now = captures.get(i);
            sameIntentions += now.intentions() == before.intentions() ? 1 : 0;
            for (MindState.IntentionView v : now.intentions()) {
                for (MindState.Means m : v.stack()) {
                    means++;
                    sameMeans += before.intentions().stream().anyMatch(w -> w.stack().stream().anyMatch(o -> o == m)) ? 1 : 0;
                }
            }
        }
        assertTrue(sameIntentions > 0, "the intentions list kept when no intended means changed");
        assertTrue(sameMeans > means / 2, sameMeans + " of " + means + " intended means kept as they were");
    }

    @Test
    void cycleByCycleThroughLoopsObjectsAndWaitsEachCaptureEqualsTheMindPrintedAnew() {
        var a = new TestAgent("""
                !count(0).
                !hold.
                !loops.
                !nap.
                +!count(N) : N < 12 <- +c(N); !count(N + 1).
                +!count(_).
                +!hold <- .queue.create(Q); +queue(Q); act(Q); .print(held).
                +c(N) : queue(Q) <- .queue.add(Q, N).
                +!loops <- for (.range(I, 1, 4)) { +seen(I) }; +tick(0); while (tick(X) & X < 3) { -+tick(X + 1) }.
                +!nap <- .wait(50); +woke.
                """);
        a.deferFeedback = true;
        MindProbe probe = MindProbe.attach(a.agent);
        var holds = new ArrayList<String>();

        for (int cycle = 0; cycle < 120; cycle++) {
            if (cycle == 60) {
                a.finishActions();
                a.advance(100, 0);
            }
            a.agent.reasoningCycle();
            MindState m = probe.capture();
            assertPrintedAnew(m, a.agent, "after cycle " + cycle);

            m.intentions().stream().flatMap(v -> v.stack().stream())
                    .filter(s -> s.trigger().startsWith("+!hold") && s.current().startsWith("act("))
                    .forEach(s -> holds.add(s.unifier()));
        }
        assertTrue(a.believes("woke"), "the wait ended");
        assertTrue(a.believes("tick(3)") && a.believes("seen(4)"), "the loops ran");
        assertTrue(holds.stream().distinct().count() > 1,
                "the queue held by a waiting intended means printed anew as it grew: " + holds);
    }

    @Test
    void aCaptureWithNothingChangedGivesTheSameLists() {
        var a = new TestAgent("""
                b(1).
                !g.
                +!g <- act; .print(done).
                """);
        a.deferFeedback = true;
        MindProbe probe = MindProbe.attach(a.agent);
        a.cycles(20);
        MindState first = probe.capture();
        MindState second = probe.capture();
        assertSame(first.beliefs(), second.beliefs());
        assertSame(first.intentions(), second.intentions());
        assertSame(first.events(), second.events());
        assertEquals(List.of("b(1)[source(self)]"), first.beliefs().stream().map(MindState.Belief::text).toList());
        a.percept("p(2)").cycles(5);
        MindState third = probe.capture();
        assertPrintedAnew(third, a.agent, "after a percept");
        assertSame(first.beliefs().get(0), third.beliefs().get(0), "the unchanged group's belief kept");
    }
}
