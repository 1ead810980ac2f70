package jacabot.cartago;

import static jacabot.cartago.Calls.assertReason;
import static jacabot.cartago.Calls.failure;
import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * CArtAgO primitives added for users' artifacts: artifacts that make, find and dispose others,
 * out ports, properties sharing a name, external sessions, and the default tuple space.
 */
class ArtifactToArtifactTest {
    public static class Cell extends Artifact {
        void init(int v) {
            defineObsProperty("value", v);
        }

        @LINK
        void set(int v) {
            getObsProperty("value").updateValue(v);
        }
    }

    @ARTIFACT_INFO(outports = @OUTPORT(name = "out"))
    public static class Maker extends Artifact {
        @OPERATION
        void make(String name, int v, OpFeedbackParam<ArtifactId> id) {
            id.set(makeArtifact(name, Cell.class.getName(), new ArtifactConfig(v)));
        }

        @OPERATION
        void makeMissing() {
            makeArtifact("m", "no.such.Class", ArtifactConfig.DEFAULT_CONFIG);
        }

        @OPERATION
        void findAndDispose(String name) {
            dispose(lookupArtifact(name));
        }

        @OPERATION
        void push(int v, OpFeedbackParam<Boolean> linked) {
            linked.set(isLinked("out"));
            execLinkedOp("out", "set", v);
        }

        @OPERATION
        void pushCaught(OpFeedbackParam<String> what) {
            try {
                execLinkedOp("nowhere", "set", 1);
            } catch (OperationException e) {
                what.set(e.getMessage());
            }
        }
    }

    @Test
    void artifactsMakeFindLinkAndDisposeOthers() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("maker", Maker.class);
            ArtifactId cell = (ArtifactId) ok(ws, agent, "make", "c1", 7, new OpFeedbackParam<>()).outputs().get(2);
            assertEquals("c1", cell.name());
            assertEquals(new AgentId("alice"), cell.creator(), "made for the agent whose operation ran");

            assertReason("unknown_class", failure(ws, agent, OpTarget.any(), "makeMissing"));
            assertReason("not_linked", failure(ws, agent, OpTarget.any(), "push", 1, new OpFeedbackParam<>()));
            assertReason("unknown_port", failure(ws, agent, OpTarget.any(), "linkArtifacts", "maker", "in", "c1"));
            ok(ws, agent, "linkArtifacts", "maker", "out", cell);
            ok(ws, agent, "focus", "c1");
            obs.expect("c1 focused [value(7)]");
            assertEquals(true, ok(ws, agent, "push", 9, new OpFeedbackParam<>()).outputs().get(1));
            obs.expect("c1 value(7)->value(9)");
            assertTrue(((String) ok(ws, agent, "pushCaught", new OpFeedbackParam<>()).outputs().get(0)).contains("nowhere"));

            ok(ws, agent, "findAndDispose", "c1");
            obs.expect("c1 disposed [value(9)]");
            assertReason("unknown_artifact", failure(ws, agent, OpTarget.any(), "findAndDispose", "c1"));
        }
    }

    public static class Board extends Artifact {
        @OPERATION
        void post(String topic, String author) {
            defineObsProperty("note", topic, author);
        }

        @OPERATION
        void unpost(String author) {
            removeObsPropertyByTemplate("note", null, author);
        }

        @OPERATION
        void count(String topic, OpFeedbackParam<Boolean> has) {
            has.set(hasObsPropertyByTemplate("note", topic, null));
        }
    }

    @Test
    void propertiesMayShareANameAndGoByTemplate() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ws.createArtifact("board", Board.class);
            ok(ws, agent, "focus", "board");
            obs.expect("board focused []");
            ok(ws, agent, "post", "a", "ann");
            ok(ws, agent, "post", "b", "bob");
            obs.expect("board +note(\"a\",\"ann\")", "board +note(\"b\",\"bob\")");
            ok(ws, agent, "unpost", "ann");
            obs.expect("board -note(\"a\",\"ann\")");
            assertEquals(false, ok(ws, agent, "count", "a", new OpFeedbackParam<>()).outputs().get(1));
            assertEquals(true, ok(ws, agent, "count", "b", new OpFeedbackParam<>()).outputs().get(1));
            assertReason("exception", failure(ws, agent, OpTarget.any(), "unpost", "nobody"));
        }
    }

    public static class Gauge extends Artifact {
        void init() {
            defineObsProperty("level", 0);
        }

        void fromOutside(int level, boolean ok) {
            beginExternalSession();
            getObsProperty("level").updateValue(level);
            endExternalSession(ok);
        }

        @OPERATION
        void read(OpFeedbackParam<Integer> level) {
            level.set(getObsProperty("level").intValue());
        }
    }

    @Test
    void externalSessionsCommitOrRollBack() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver obs = new RecordingObserver();
            AgentId agent = ws.join("alice", obs);
            ArtifactId id = ws.createArtifact("gauge", Gauge.class);
            ok(ws, agent, "focus", "gauge");
            obs.expect("gauge focused [level(0)]");
            Gauge gauge = ws.artifactObject(id, Gauge.class).orElseThrow();
            Thread outside = new Thread(() -> {
                gauge.fromOutside(5, true);
                gauge.fromOutside(6, false);
            });
            outside.start();
            outside.join(10_000);
            obs.expect("gauge level(0)->level(5)");
            assertEquals(5, ok(ws, agent, "read", new OpFeedbackParam<>()).outputs().get(0));
            assertEquals(List.of(), obs.drain());
        }
    }

    @Test
    void theBlackboardBindsUnboundVariablesAndWaits() throws Exception {
        try (Workspace ws = Calls.quiet("main").build()) {
            AgentId agent = ws.join("alice", new ArtifactObserverAdapter());
            var waiting = Calls.start(ws, agent, OpTarget.name("blackboard"), "in", "pair", "k", new OpFeedbackParam<>());
            ok(ws, agent, "out", "pair", "j", 1);
            ok(ws, agent, "out", "pair", "k", 2);
            OpOutcome got = waiting.get(10, TimeUnit.SECONDS);
            assertEquals(2, ((OpOutcome.Success) got).outputs().get(2));
            assertEquals("j", ok(ws, agent, "rd", "pair", new OpFeedbackParam<>(), 1).outputs().get(1));
            assertReason("no_match", failure(ws, agent, OpTarget.any(), "inp", "pair", "k", new OpFeedbackParam<>()));
        }
    }
}
