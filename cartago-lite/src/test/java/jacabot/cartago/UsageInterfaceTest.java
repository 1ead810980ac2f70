package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.cartago.examples.Counter;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What a workspace tells about an artifact (a debugger's artifacts panel): its usage interface and who focuses on it. */
class UsageInterfaceTest {
    /** A counter that can also be reset to a value and tells the old one; its tick is its own. */
    public static class ResettableCounter extends Counter {
        @OPERATION
        void reset(int value, OpFeedbackParam<Integer> old) {
            old.set(value);
        }

        @INTERNAL_OPERATION
        void housekeeping() {
        }

        void helper() {
        }
    }

    @Test
    void operationsWithTheirArityInheritedOnesTooAndTheFocusers() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId alice = ws.join("alice", new RecordingObserver());
            AgentId bob = ws.join("bob", new RecordingObserver());
            ArtifactId c = Calls.makeArtifact(ws, alice, "c0", ResettableCounter.class);
            assertEquals(List.of("inc/0", "reset/2"), ws.operationsOf(c), "not the internal operation, not a plain method");
            assertEquals(List.of(), ws.observersOf(c));
            ok(ws, bob, "focus", c);
            ok(ws, alice, "focus", c);
            assertEquals(List.of(bob, alice), ws.observersOf(c));
            ws.disposeArtifact(c);
            assertEquals(List.of(), ws.operationsOf(c));
        }
    }
}
