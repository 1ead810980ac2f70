package jacabot.cartago;

import static jacabot.cartago.Calls.failure;
import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.BoundedCounter;
import java.util.List;
import org.junit.jupiter.api.Test;

/** failed() and exceptions roll back what the step changed since its last commit point. */
class RollbackTest {
    /** Changes properties in every way, commits at chosen points, then fails. */
    public static class Editor extends Artifact {
        private ObsProperty a;

        void init() {
            a = defineObsProperty("a", 1);
            defineObsProperty("b", "x");
        }

        @OPERATION
        void mangle(boolean commitFirst, boolean throwInstead) {
            a.updateValue(2);
            if (commitFirst) {
                commit();
            }
            a.updateValue(3);
            removeObsProperty("b");
            defineObsProperty("c", true);
            if (throwInstead) {
                throw new IllegalStateException("boom");
            }
            failed("mangled", "mangled", 7);
        }

        @OPERATION
        void show(OpFeedbackParam<String> text) {
            text.set(a.intValue() + " " + hasObsProperty("b") + " " + getObsProperty("b") + " " + hasObsProperty("c"));
        }

        @OPERATION
        void touchA() {
            a.updateValue(a.intValue() + 10);
        }
    }

    @Test
    void failedRestoresUpdatedRemovedAndDefinedProperties() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("ed", Editor.class);
            ok(ws, agent, "focus", "ed");
            obs.expect("ed focused [a(1), b(\"x\")]");

            OpOutcome.Failure f = failure(ws, agent, OpTarget.any(), "mangle", false, false);
            assertEquals(new OpOutcome.Failure("mangled", "mangled", List.of(7)), f);
            assertEquals(List.of(), obs.drain(), "nothing was committed");
            assertEquals("1 true b(\"x\") false", ok(ws, agent, "show", new OpFeedbackParam<String>()).outputs().get(0));

            // The ObsProperty kept in a field is still the live one after the rollback.
            ok(ws, agent, "touchA");
            obs.expect("ed a(1)->a(11)");
        }
    }

    @Test
    void onlyChangesAfterTheLastCommitAreRolledBack() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("ed", Editor.class);
            ok(ws, agent, "focus", "ed");
            obs.next();

            OpOutcome.Failure f = failure(ws, agent, OpTarget.any(), "mangle", true, true);
            assertEquals("exception", f.reasonFunctor());
            assertTrue(f.message().contains("boom"), f.message());
            obs.expect("ed a(1)->a(2)");
            assertEquals(List.of(), obs.drain());
            assertEquals("2 true b(\"x\") false", ok(ws, agent, "show", new OpFeedbackParam<String>()).outputs().get(0));
        }
    }

    @Test
    void aBoundedCounterFailsAtItsMaximumAndKeepsItsValue() {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ArtifactId id = Calls.makeArtifact(ws, agent, "bc", BoundedCounter.class, 2.0);
            ok(ws, agent, "focus", id);
            ok(ws, agent, "inc");
            ok(ws, agent, "inc");
            OpOutcome.Failure f = failure(ws, agent, OpTarget.id(id), "inc");
            assertEquals("inc failed: the counter is at its maximum 2", f.message());
            assertEquals("max_reached", f.reasonFunctor());
            assertEquals(List.of(2), f.reasonArgs());
            obs.expect("bc focused [count(0)]", "bc count(0)->count(1)", "bc count(1)->count(2)");
            ok(ws, agent, "stopFocus", id);
            obs.expect("bc unfocused [count(2)]");
        }
    }
}
