package jacabot.cartago;

import static jacabot.cartago.Calls.ok;
import static org.junit.jupiter.api.Assertions.assertEquals;

import jacabot.cartago.examples.Counter;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which artifact an operation without target goes to, and who the caller is. */
class ResolutionTest {
    /** Tells who called, and signals the caller alone. */
    public static class Desk extends Artifact {
        @OPERATION
        void whoAmI(OpFeedbackParam<String> name) {
            name.set(getCurrentOpAgentId().getAgentName());
            signal(getCurrentOpAgentId(), "hello", getCurrentOpAgentId().name());
        }
    }

    /** Tells its own name, with one argument or two. */
    public static class Named extends Artifact {
        @OPERATION
        void who(OpFeedbackParam<String> name) {
            name.set(getId().name());
        }

        @OPERATION
        void who(String prefix, OpFeedbackParam<String> name) {
            name.set(prefix + getId().name());
        }
    }

    /** Several methods of one name: exact arities before varargs, an internal operation never for an agent. */
    public static class Overloads extends Artifact {
        void init() {
            defineObsProperty("ran", "none");
        }

        @OPERATION
        void put(int x) {
            getObsProperty("ran").updateValue("one");
        }

        @OPERATION
        void put(int x, int y) {
            getObsProperty("ran").updateValue("two");
        }

        @OPERATION
        void put(Object... xs) {
            getObsProperty("ran").updateValue("varargs of " + xs.length);
        }

        @INTERNAL_OPERATION
        void put(int x, int y, int z) {
            getObsProperty("ran").updateValue("internal");
        }
    }

    /**
     * The method an operation runs is the one the ordered candidates give: the one method of that
     * name and arity is bound at once, several are ordered (exact before varargs), and an artifact
     * without a method of that name, or with one of another kind, is passed over.
     */
    @Test
    void theMethodIsTheFirstOfItsNameAndArityExactBeforeVarargs() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver bobSees = new RecordingObserver();
            AgentId bob = ws.join("bob", bobSees);
            ws.createArtifact("desk", Desk.class);
            ws.createArtifact("overloads", Overloads.class);
            ok(ws, bob, "focus", "overloads");
            bobSees.drain();
            ok(ws, bob, "put", 1);
            ok(ws, bob, "put", 1, 2);
            ok(ws, bob, "put", 1, 2, 3);
            ok(ws, bob, "put");
            bobSees.expect("overloads ran(\"none\")->ran(\"one\")", "overloads ran(\"one\")->ran(\"two\")",
                    "overloads ran(\"two\")->ran(\"varargs of 3\")", "overloads ran(\"varargs of 3\")->ran(\"varargs of 0\")");
            Calls.assertReason("wrong_arity", Calls.failure(ws, bob, OpTarget.any(), "whoAmI", 1, 2));
        }
    }

    @Test
    void createdThenFocusedThenOldest() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver bobSees = new RecordingObserver();
            RecordingObserver carolSees = new RecordingObserver();
            AgentId alice = ws.join("alice", new RecordingObserver());
            AgentId bob = ws.join("bob", bobSees);
            AgentId carol = ws.join("carol", carolSees);
            ArtifactId first = ws.createArtifact("first", Counter.class);
            ArtifactId bobs = Calls.makeArtifact(ws, bob, "bobs", Counter.class);
            ArtifactId thirds = ws.createArtifact("third", Counter.class);
            ok(ws, bob, "focus", first);
            ok(ws, bob, "focus", bobs);
            ok(ws, carol, "focus", thirds);
            ok(ws, carol, "focus", bobs);
            bobSees.drain();
            carolSees.drain();

            ok(ws, bob, "inc"); // bob created bobs
            ok(ws, carol, "inc"); // carol focuses third first
            ok(ws, alice, "inc"); // alice: the oldest, first
            bobSees.expect("bobs count(0)->count(1)", "bobs !tick", "first count(0)->count(1)", "first !tick");
            carolSees.expect("bobs count(0)->count(1)", "bobs !tick", "third count(0)->count(1)", "third !tick");
            assertEquals(List.of(bob, carol), ws.observersOf(bobs));
        }
    }

    @Test
    void anArtifactCreatedAndFocusedWithoutTheOperationIsPassedOverForTheNextThatHasIt() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver bobSees = new RecordingObserver();
            AgentId bob = ws.join("bob", bobSees);
            ws.createArtifact("older", Counter.class);
            ArtifactId desk = Calls.makeArtifact(ws, bob, "desk", Desk.class);
            ArtifactId counter = ws.createArtifact("counter", Counter.class);
            ok(ws, bob, "focus", desk);
            ok(ws, bob, "focus", counter);
            bobSees.drain();
            // desk comes first (created, then focused) and has no inc: the next is counter, focused, before the older one
            ok(ws, bob, "inc");
            bobSees.expect("counter count(0)->count(1)", "counter !tick");
            assertEquals("bob", ok(ws, bob, "whoAmI", new OpFeedbackParam<>()).outputs().get(0));
        }
    }

    @Test
    void theCallerIsKnownAndCanBeSignalledAlone() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver aliceSees = new RecordingObserver();
            RecordingObserver bobSees = new RecordingObserver();
            AgentId alice = ws.join("alice", aliceSees);
            AgentId bob = ws.join("bob", bobSees);
            ws.createArtifact("desk", Desk.class);
            ok(ws, bob, "focus", "desk");
            bobSees.next();
            assertEquals("alice", ok(ws, alice, "whoAmI", new OpFeedbackParam<>()).outputs().get(0));
            aliceSees.expect("desk !hello[alice]");
            assertEquals(List.of(), bobSees.drain(), "a signal to alice does not reach bob, though he focuses the desk");
        }
    }

    @Test
    void eachAgentsFocusGoesToItsOwnBody() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").build()) {
            RecordingObserver aliceSees = new RecordingObserver();
            RecordingObserver bobSees = new RecordingObserver();
            AgentId alice = ws.join("alice", aliceSees);
            AgentId bob = ws.join("bob", bobSees);
            ws.createArtifact("c0", Counter.class);
            ok(ws, bob, "focus", "c0");
            bobSees.expect("c0 focused [count(0)]");
            assertEquals(List.of(), aliceSees.drain());
            ws.leave(bob);
            bobSees.expect("c0 unfocused [count(0)]");
            assertEquals(List.of(), ws.observersOf(ws.lookup("c0").orElseThrow()));
            ok(ws, alice, "inc");
        }
    }
    /** The live artifacts are kept between operations ({@code Workspace.cores}) until one comes or goes. */
    @Test
    void anArtifactMadeOrDisposedBetweenTwoOperationsIsSeenByTheNext() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            RecordingObserver bobSees = new RecordingObserver();
            AgentId bob = ws.join("bob", bobSees);
            ws.createArtifact("counter", Counter.class);
            ok(ws, bob, "inc");
            Calls.assertReason("unknown_operation", Calls.failure(ws, bob, OpTarget.any(), "whoAmI", new OpFeedbackParam<>()));
            ArtifactId desk = ws.createArtifact("desk", Desk.class);
            assertEquals("bob", ok(ws, bob, "whoAmI", new OpFeedbackParam<>()).outputs().get(0));
            ws.disposeArtifact(desk);
            Calls.assertReason("unknown_operation", Calls.failure(ws, bob, OpTarget.any(), "whoAmI", new OpFeedbackParam<>()));
            ArtifactId other = ws.createArtifact("other", Counter.class);
            ws.disposeArtifact(ws.lookup("counter").orElseThrow());
            ok(ws, bob, "focus", other);
            bobSees.drain();
            ok(ws, bob, "inc");
            bobSees.expect("other count(0)->count(1)", "other !tick");
        }
    }

    private static String who(Workspace ws, AgentId agent) {
        String once = (String) ok(ws, agent, "who", new OpFeedbackParam<>()).outputs().get(0);
        assertEquals(once, ok(ws, agent, "who", new OpFeedbackParam<>()).outputs().get(0), "asked again");
        assertEquals("to " + once, ok(ws, agent, "who", "to ", new OpFeedbackParam<>()).outputs().get(1), "another arity");
        return once;
    }

    /**
     * Where an operation without a target went is kept ({@code OpRoutes}) only while the artifacts
     * and the agents' focus stay as they were: each change below moves the answer, asked twice.
     */
    @Test
    void theArtifactAnOperationGoesToFollowsArtifactsAndFocusAsTheyChange() throws CartagoException {
        try (Workspace ws = Calls.quiet("main").stepped().build()) {
            AgentId bob = ws.join("bob", new RecordingObserver());
            AgentId alice = ws.join("alice", new RecordingObserver());
            ws.createArtifact("oldest", Named.class);
            assertEquals("oldest", who(ws, bob));
            ArtifactId made = Calls.makeArtifact(ws, bob, "bobs", Named.class);
            assertEquals("bobs", who(ws, bob), "made by bob: his first");
            assertEquals("oldest", who(ws, alice), "alice made none");
            ArtifactId focused = ws.createArtifact("focused", Named.class);
            ok(ws, bob, "focus", focused);
            assertEquals("bobs", who(ws, bob), "made before focused");
            ok(ws, alice, "focus", focused);
            assertEquals("focused", who(ws, alice), "focused before the oldest");
            ws.disposeArtifact(made);
            assertEquals("focused", who(ws, bob));
            ok(ws, bob, "stopFocus", focused);
            assertEquals("oldest", who(ws, bob), "no longer focused");
            assertEquals("focused", who(ws, alice), "alice still focuses it");
            ws.leave(alice);
            AgentId again = ws.join("alice", new RecordingObserver());
            assertEquals("oldest", who(ws, again), "joined anew: focuses nothing");
            ws.disposeArtifact(ws.lookup("oldest").orElseThrow());
            assertEquals("focused", who(ws, bob), "the oldest left");
        }
    }
}
