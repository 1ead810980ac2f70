package jacabot.cartago;

import static jacabot.cartago.Calls.assertReason;
import static jacabot.cartago.Calls.failure;
import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** execLinkedOp: one artifact using another's @LINK operation. */
class LinkTest {
    /** Keeps lines; only linked artifacts may write. */
    public static class Logbook extends Artifact {
        void init() {
            defineObsProperty("lines", 0);
        }

        @LINK
        void write(String line, OpFeedbackParam<Integer> count) {
            if (line.isEmpty()) {
                failed("empty line", "empty_line");
            }
            int lines = getObsProperty("lines").intValue() + 1;
            getObsProperty("lines").updateValue(lines);
            count.set(lines);
        }
    }

    /** Forwards lines to a logbook and counts what it sent. */
    public static class Relay extends Artifact {
        void init() {
            defineObsProperty("sent", 0);
        }

        @OPERATION
        void send(ArtifactId logbook, String line, OpFeedbackParam<Integer> count) {
            execLinkedOp(logbook, "write", line, count);
            getObsProperty("sent").updateValue(getObsProperty("sent").intValue() + 1);
        }
    }

    private static void runLinks(Workspace ws) throws CartagoException {
        RecordingObserver obs = new RecordingObserver();
        AgentId agent = ws.join("alice", obs);
        ArtifactId logbook = ws.createArtifact("logbook", Logbook.class);
        ws.createArtifact("relay", Relay.class);
        ok(ws, agent, "focus", "logbook");
        ok(ws, agent, "focus", "relay");
        obs.expect("logbook focused [lines(0)]", "relay focused [sent(0)]");

        assertEquals(1, ok(ws, agent, "send", logbook, "one", new OpFeedbackParam<>()).outputs().get(2));
        obs.expect("logbook lines(0)->lines(1)", "relay sent(0)->sent(1)");

        OpOutcome.Failure f = failure(ws, agent, OpTarget.any(), "send", logbook, "", new OpFeedbackParam<>());
        assertEquals(new OpOutcome.Failure("empty line", "empty_line", List.of()), f);
        assertReason("unknown_operation", failure(ws, agent, OpTarget.any(), "write", "x", new OpFeedbackParam<>()));
        assertEquals(List.of(), obs.drain());
    }

    @Test
    void linkedOperationsWhenThreaded() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            runLinks(ws);
        }
    }

    @Test
    void linkedOperationsWhenStepped() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            runLinks(ws);
        }
    }
}
