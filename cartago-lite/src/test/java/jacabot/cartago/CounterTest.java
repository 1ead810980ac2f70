package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.cartago.examples.Counter;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The thesis' counter (Chapter 2, section 4.2): the agent's side played by Java calls. */
class CounterTest {
    /** makeArtifact, lookupArtifact, focus, then inc: the observer sees count change, then tick. */
    private void runCounterScenario(Workspace ws) {
        RecordingObserver alice = new RecordingObserver();
        AgentId agent = ws.join("alice", alice);

        ArtifactId made = Calls.makeArtifact(ws, agent, "c0", Counter.class);
        ArtifactId looked = (ArtifactId) ok(ws, agent, "lookupArtifact", "c0", new OpFeedbackParam<ArtifactId>()).outputs().get(1);
        assertEquals(made, looked);
        assertEquals(agent, made.creator());

        ok(ws, agent, "focus", looked);
        alice.expect("c0 focused [count(0)]");

        ok(ws, agent, "inc");
        ok(ws, agent, "inc");
        alice.expect("c0 count(0)->count(1)", "c0 !tick", "c0 count(1)->count(2)", "c0 !tick");
    }

    @Test
    void threadedCounterReportsEachIncrementThenTheTick() {
        try (Workspace ws = Calls.quiet("main").build()) {
            runCounterScenario(ws);
        }
    }

    @Test
    void steppedCounterReportsEachIncrementThenTheTick() {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            runCounterScenario(ws);
        }
    }

    @Test
    void theConsolePrintsLikeJason() {
        Calls.Console console = new Calls.Console();
        try (Workspace ws = Calls.quiet("main").console(console.out).stepped().build()) {
            AgentId agent = ws.join("counter_user", new RecordingObserver());
            ok(ws, agent, "println", "observed new value: ", 1.0);
            ok(ws, agent, "println", "perceived a tick");
            ok(ws, agent, "print", "x = ", 2.5, " list ", List.of(1.0, "a"));
            assertEquals("[counter_user] observed new value: 1\n[counter_user] perceived a tick\n"
                    + "[counter_user] x = 2.5 list [1,\"a\"]", console.text());
        }
    }

    @Test
    void stopFocusAndDisposalEndTheObservation() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver alice = new RecordingObserver();
            AgentId agent = ws.join("alice", alice);
            ArtifactId c0 = ws.createArtifact("c0", Counter.class);
            ArtifactId c1 = ws.createArtifact("c1", Counter.class.getName());
            ok(ws, agent, "focus", c0);
            ok(ws, agent, "focus", "c1");
            alice.expect("c0 focused [count(0)]", "c1 focused [count(0)]");
            assertEquals(List.of(c0, c1), ws.focusedBy(agent));

            ok(ws, agent, "stopFocus", c0);
            alice.expect("c0 unfocused [count(0)]");
            Calls.call(ws, agent, OpTarget.id(c0), "inc");
            ok(ws, agent, "disposeArtifact", c1);
            alice.expect("c1 disposed [count(0)]");
            assertEquals(List.of(), ws.focusedBy(agent));
            assertEquals(Optional.empty(), ws.lookup("c1"));
            assertEquals(List.of(), alice.drain(), "no event from c0 after stopFocus");
        }
    }
}
