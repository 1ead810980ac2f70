package jacabot.cartago;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.examples.Counter;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link Artifact#agentLeft}: an artifact lets go of what an agent held once it leaves the
 * workspace, and the agents still there perceive the change.
 */
class AgentLeftTest {
    /** Holds one token at a time; the holder's leaving frees it. */
    public static class Token extends Artifact {
        void init() {
            defineObsProperty("holder", "none");
        }

        @OPERATION
        void take() {
            if (!getObsProperty("holder").stringValue().equals("none")) {
                failed("taken", "taken");
            }
            getObsProperty("holder").updateValue(getCurrentOpAgentId().name());
        }

        @Override
        protected void agentLeft(AgentId agent) {
            if (getObsProperty("holder").stringValue().equals(agent.name())) {
                getObsProperty("holder").updateValue("none");
                signal("freed", agent.name());
            }
        }
    }

    /** Throws from its hook: the workspace logs it and goes on. */
    public static class Faulty extends Artifact {
        final List<String> calls = new ArrayList<>();

        @Override
        protected void agentLeft(AgentId agent) {
            calls.add(agent.name());
            throw new IllegalStateException("boom");
        }
    }

    @Test
    void theHolderLeavingFreesTheTokenAndTheOthersPerceiveIt() throws CartagoException {
        for (Workspace.Mode mode : Workspace.Mode.values()) {
            Workspace.Builder b = Calls.quiet("room");
            try (Workspace ws = (mode == Workspace.Mode.STEPPED ? b.stepped() : b).build()) {
                ArtifactId faultyId = ws.createArtifact("faulty", Faulty.class);
                ws.createArtifact("token", Token.class);
                AgentId alice = ws.join("alice", new RecordingObserver());
                RecordingObserver bobSees = new RecordingObserver();
                AgentId bob = ws.join("bob", bobSees);
                Calls.ok(ws, alice, "take");
                Calls.ok(ws, bob, "focus", "token");
                bobSees.expect("token focused [holder(\"alice\")]");
                Calls.assertReason("taken", Calls.failure(ws, bob, OpTarget.any(), "take"));

                ws.leave(alice);
                if (mode == Workspace.Mode.STEPPED) {
                    ws.runPending();
                }
                bobSees.expect("token holder(\"alice\")->holder(\"none\")", "token !freed[alice]");
                Calls.ok(ws, bob, "take");
                bobSees.expect("token holder(\"none\")->holder(\"bob\")");
                Faulty faulty = ws.artifactObject(faultyId, Faulty.class).orElseThrow();
                assertEquals(List.of("alice"), faulty.calls, mode + ": the hook ran once, its failure logged, not thrown");
            }
        }
    }

    @Test
    void anArtifactWithoutTheHookIsNotTouched() throws CartagoException {
        try (Workspace ws = Calls.quiet("room").build()) {
            ws.createArtifact("c0", Counter.class);
            AgentId alice = ws.join("alice", new RecordingObserver());
            ws.leave(alice);
            assertTrue(ws.agents().isEmpty());
            assertTrue(ws.lookup("c0").isPresent());
        }
    }
}
