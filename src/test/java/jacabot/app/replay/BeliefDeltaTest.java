package jacabot.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.agent.semantics.Agent;
import jacabot.agent.testing.TestAgent;
import jacabot.app.inspector.BeliefList;
import jacabot.app.inspector.MindProbe;
import jacabot.app.inspector.MindState;
import jacabot.app.run.AgentSource;
import jacabot.app.run.LockstepRun;
import jacabot.robot.Experiment;
import jacabot.sim.SimWorld;
import jacabot.sim.io.WorldFileReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The step log's belief delta read group by group from the probe's captures is the delta of the
 * whole lists (the beliefs copied into plain lists, compared text by text): on a real run, where
 * properties move their groups to the end at every step, and through rules, loops and groups that
 * come and go; with a key step (everything added anew) every few steps.
 */
class BeliefDeltaTest {
    /** Compares the two deltas of each capture; {@return how many captures changed the beliefs} */
    private static final class Both {
        final BeliefDelta byGroups = new BeliefDelta();
        final BeliefDelta whole = new BeliefDelta();
        List<MindState.Belief> lastCapture;
        List<MindState.Belief> lastCopy;
        int changed;
        int steps;

        void compare(MindState m, String where) {
            assertTrue(m.beliefs() instanceof BeliefList, "the probe gives its grouped list");
            if (steps++ % 7 == 0) {
                byGroups.reset();
                whole.reset();
            }
            // a plain copy, the same object while the probe's list is (as the probe's own answers)
            List<MindState.Belief> copy = m.beliefs() == lastCapture ? lastCopy : new ArrayList<>(m.beliefs());
            lastCapture = m.beliefs();
            lastCopy = copy;
            var added = new ArrayList<MindState.Belief>();
            var removed = new ArrayList<String>();
            var addedWhole = new ArrayList<MindState.Belief>();
            var removedWhole = new ArrayList<String>();
            boolean any = byGroups.between(m.beliefs(), added, removed);
            assertEquals(any, whole.between(copy, addedWhole, removedWhole), where);
            assertEquals(addedWhole, added, "added " + where);
            assertEquals(removedWhole, removed, "removed " + where);
            changed += added.isEmpty() && removed.isEmpty() ? 0 : 1;
        }
    }

    @Test
    void aRealRunsDeltasByGroupAreThoseOfTheWholeLists() throws Exception {
        Experiment x = Experiment.parse("suspend-resume").orElseThrow();
        var run = new LockstepRun(SimWorld.of(WorldFileReader.read(RunTapTest.ROOT.resolve(x.worldFile()))), null, x,
                AgentSource.packaged(x), 13, new PrintStream(OutputStream.nullOutputStream()));
        Agent agent = run.mas().agent(run.agentNames().get(0));
        MindProbe probe = MindProbe.attach(agent);
        var both = new Both();
        run.onCommands((data, commands) -> both.compare(probe.capture(), "at " + data.simTimeMs() + " ms"));
        run.runFor(20);
        assertTrue(both.steps >= 400 && both.changed > both.steps / 2, both.changed + " of " + both.steps + " steps changed beliefs");
    }

    @Test
    void rulesLoopsAndGroupsThatComeAndGoGiveTheDeltasOfTheWholeLists() {
        var a = new TestAgent("""
                b(1).
                b(2).
                r(X) :- b(X).
                !count(0).
                !loops.
                +!count(N) : N < 15 <- +c(N); -+last(N); .abolish(b(_)); +b(N); +b(N + 1); !count(N + 1).
                +!count(_) <- +{ r(X) :- c(X) }; .abolish(c(_)).
                +!loops <- for (.range(I, 1, 6)) { +seen(I); -seen(I - 2) }; +tick(0); while (tick(X) & X < 5) { -+tick(X + 1) }.
                """);
        MindProbe probe = MindProbe.attach(a.agent);
        var both = new Both();
        for (int cycle = 0; cycle < 400; cycle++) {
            a.agent.reasoningCycle();
            both.compare(probe.capture(), "after cycle " + cycle);
        }
        assertTrue(a.believes("tick(5)") && a.believes("last(14)"), "the program ran");
        assertTrue(both.changed > 30, both.changed + " captures changed beliefs");
    }
}
