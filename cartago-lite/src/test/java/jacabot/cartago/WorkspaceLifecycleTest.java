package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.BoundedBuffer;
import jacabot.cartago.examples.Counter;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** Closing a workspace, logging, and the default artifacts. */
class WorkspaceLifecycleTest {
    /** Logs through the workspace's logger and counts its disposals. */
    public static class Noisy extends Artifact {
        @OPERATION
        void say(String text) {
            log(text);
        }

        @Override
        protected void dispose() {
            log("disposed");
        }
    }

    @Test
    void closingFailsWaitingOperationsAndRefusesNewOnes() throws Exception {
        RecordingLogger log = new RecordingLogger();
        Workspace ws = Workspace.builder("main").logger(log).build();
        AgentId agent = ws.join("alice", new RecordingObserver());
        ArtifactId buffer = ws.createArtifact("buffer", BoundedBuffer.class, 1);
        ws.createArtifact("noisy", Noisy.class);
        ok(ws, agent, "say", "hello");
        assertEquals("info noisy: hello", log.next());

        CompletableFuture<OpOutcome> get = Calls.start(ws, agent, OpTarget.id(buffer), "get", new OpFeedbackParam<>());
        ws.close();
        assertEquals("info noisy: disposed", log.next());
        OpOutcome.Failure waiting = (OpOutcome.Failure) get.get(10, TimeUnit.SECONDS);
        assertTrue(List.of("artifact_disposed", "interrupted").contains(waiting.reasonFunctor()), waiting.toString());

        OpOutcome late = Calls.start(ws, agent, OpTarget.any(), "inc").get(10, TimeUnit.SECONDS);
        assertEquals("workspace_closed", ((OpOutcome.Failure) late).reasonFunctor());
        ws.close();
    }

    @Test
    void steppedWorkspacesCloseToo() throws CartagoException {
        Workspace ws = Calls.quiet("main").stepped().build();
        AgentId agent = ws.join("alice", new RecordingObserver());
        ws.createArtifact("buffer", BoundedBuffer.class, 1);
        CompletableFuture<OpOutcome> get = Calls.start(ws, agent, OpTarget.any(), "get", new OpFeedbackParam<>());
        ws.runPending();
        ws.close();
        assertEquals("workspace_closed",
                ((OpOutcome.Failure) Calls.start(ws, agent, OpTarget.any(), "put", 1).join()).reasonFunctor());
        assertTrue(!get.isDone() || !get.join().succeeded());
    }

    @Test
    void everyWorkspaceStartsWithItsOwnArtifacts() throws CartagoException {
        try (Workspace ws = Calls.quiet("room").build()) {
            AgentId agent = ws.join("alice", new RecordingObserver());
            ArtifactId c0 = ws.createArtifact("c0", Counter.class);
            assertEquals("room", c0.workspace());
            assertEquals(Counter.class.getName(), c0.getArtifactType());
            assertEquals("cobj_" + c0.id(), c0.toString());
            assertEquals(List.of("workspace", "console", "blackboard", "body_alice", "c0"),
                    ws.artifacts().stream().map(ArtifactId::getName).collect(Collectors.toList()));
            assertEquals(List.of(agent), ws.agents());
            assertEquals(agent, ws.lookup("body_alice").orElseThrow().creator());
            ws.leave(agent);
            assertEquals(List.of(), ws.agents());
            assertTrue(ws.lookup("body_alice").isEmpty());
        }
    }
}
