package jacabot.cartago;

import static jacabot.cartago.Calls.assertReason;
import static jacabot.cartago.Calls.failure;
import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.BoundedCounter;
import jacabot.cartago.examples.Counter;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** Each bad request fails its operation with a clear reason, and nothing else breaks. */
class BadInputTest {
    /** init fails for negative sizes, throws for zero, and may not await. */
    public static class Picky extends Artifact {
        void init(int size) {
            if (size < 0) {
                failed("negative size " + size);
            }
            if (size == 0) {
                throw new IllegalArgumentException("zero size");
            }
            defineObsProperty("size", size);
        }

        void init(String mode) {
            await_time(1);
        }
    }

    /** Names a guard that does not exist. */
    public static class BadGuard extends Artifact {
        @OPERATION(guard = "ready")
        void go() {
        }
    }

    private static OpOutcome.Failure make(Workspace ws, AgentId agent, String name, String className, Object... params) {
        return failure(ws, agent, OpTarget.any(), "makeArtifact", name, className, params, new OpFeedbackParam<>());
    }

    private static void runAllBadInputs(Workspace ws) {
        AgentId agent = ws.join("alice", new RecordingObserver());
        ArtifactId c0 = Calls.makeArtifact(ws, agent, "c0", Counter.class);

        OpOutcome.Failure f = make(ws, agent, "x", "no.such.Artifact");
        assertReason("unknown_class", f);
        assertEquals("unknown artifact class no.such.Artifact", f.message());
        assertReason("not_an_artifact", make(ws, agent, "x", "java.lang.String"));
        f = make(ws, agent, "x", Picky.class.getName(), -1);
        assertReason("init_failed", f);
        assertTrue(f.message().endsWith("failed: negative size -1"), f.message());
        f = make(ws, agent, "x", Picky.class.getName(), 0);
        assertReason("init_failed", f);
        assertTrue(f.message().contains("zero size"), f.message());
        f = make(ws, agent, "x", Picky.class.getName(), "waiting");
        assertReason("init_failed", f);
        assertTrue(f.message().contains("await is not allowed in init"), f.message());
        assertReason("init_failed", make(ws, agent, "x", BoundedCounter.class.getName(), 1, 2));
        assertReason("init_failed", make(ws, agent, "x", BoundedCounter.class.getName(), "ten"));
        f = make(ws, agent, "x", BadGuard.class.getName());
        assertReason("bad_artifact_class", f);
        assertTrue(f.message().contains("no @GUARD ready"), f.message());
        f = make(ws, agent, "c0", Counter.class.getName());
        assertReason("duplicate_name", f);
        assertEquals(List.of("c0"), f.reasonArgs());

        f = failure(ws, agent, OpTarget.any(), "fly");
        assertReason("unknown_operation", f);
        assertEquals("no artifact in workspace main has operation fly/0", f.message());
        f = failure(ws, agent, OpTarget.any(), "inc", 1);
        assertReason("wrong_arity", f);
        assertEquals("no artifact in workspace main has operation inc/1 (c0 has inc/0)", f.message());
        f = failure(ws, agent, OpTarget.name("c0"), "inc", 1, 2);
        assertReason("wrong_arity", f);
        assertReason("unknown_operation", failure(ws, agent, OpTarget.id(c0), "dec"));
        f = failure(ws, agent, OpTarget.name("nope"), "inc");
        assertReason("unknown_artifact", f);
        assertEquals("no artifact nope in workspace main", f.message());
        assertReason("unknown_artifact", failure(ws, agent, OpTarget.any(), "lookupArtifact", "nope", new OpFeedbackParam<>()));
        assertReason("unknown_artifact", failure(ws, agent, OpTarget.any(), "focus", "nope"));
        assertReason("not_focused", failure(ws, agent, OpTarget.any(), "stopFocus", c0));
        assertReason("cannot_dispose", failure(ws, agent, OpTarget.any(), "disposeArtifact", "workspace"));
        assertReason("cannot_dispose", failure(ws, agent, OpTarget.any(), "disposeArtifact", "body_alice"));
        assertReason("cannot_focus", failure(ws, agent, OpTarget.any(), "focus", "body_alice"));
        assertReason("unknown_agent", failure(ws, new AgentId("ghost"), OpTarget.any(), "inc"));

        // Nothing else broke: no half-made artifact, c0 works, the failed names are free.
        assertEquals(List.of("workspace", "console", "blackboard", "body_alice", "c0"),
                ws.artifacts().stream().map(ArtifactId::name).collect(Collectors.toList()));
        ok(ws, agent, "inc");
        ok(ws, agent, "makeArtifact", "x", Picky.class.getName(), new Object[] {3});
        ok(ws, agent, "disposeArtifact", c0);
        assertReason("unknown_artifact", failure(ws, agent, OpTarget.id(c0), "inc"));
    }

    @Test
    void badInputsFailCleanlyWhenThreaded() {
        try (Workspace ws = Calls.quiet("main").build()) {
            runAllBadInputs(ws);
        }
    }

    @Test
    void badInputsFailCleanlyWhenStepped() {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            runAllBadInputs(ws);
        }
    }

    @Test
    void javaCallersGetTheSameFailuresAsExceptions() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            CartagoException e = assertThrows(CartagoException.class, () -> ws.createArtifact("x", "no.such.Artifact"));
            assertReason("unknown_class", e.failure());
            ws.createArtifact("c0", Counter.class);
            e = assertThrows(CartagoException.class, () -> ws.createArtifact("c0", Counter.class));
            assertReason("duplicate_name", e.failure());
            ws.join("alice", new RecordingObserver());
            assertThrows(IllegalArgumentException.class, () -> ws.join("alice", new RecordingObserver()));
            assertThrows(IllegalStateException.class, ws::runPending);
        }
    }

    /** Hands itself out, so that the test can call it from outside any step. */
    public static class Leaky extends Artifact {
        void init() {
            defineObsProperty("count", 0);
        }

        @OPERATION
        void leak(OpFeedbackParam<Object> self) {
            self.set(this);
        }

        public Object peek() {
            return getObsProperty("count");
        }
    }

    @Test
    void primitivesOutsideAStepAreRefused() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            ws.createArtifact("leaky", Leaky.class);
            Leaky leaked = (Leaky) ok(ws, agent, "leak", new OpFeedbackParam<>()).outputs().get(0);
            IllegalStateException e = assertThrows(IllegalStateException.class, leaked::peek);
            assertTrue(e.getMessage().contains("only be used inside one of its operations"), e.getMessage());
        }
    }
}
