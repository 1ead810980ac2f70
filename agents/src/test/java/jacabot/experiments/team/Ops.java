package jacabot.experiments.team;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.CartagoLogger;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/** Calls the team artifacts' operations as agents would, and what an agent focusing them perceives. */
final class Ops {
    private Ops() {
    }

    /** {@return a quiet threaded workspace} */
    static Workspace workspace() {
        return Workspace.builder("team").logger(CartagoLogger.silent()).build();
    }

    /** Asks for {@code op(args...)} on the artifact called {@code artifact}; {@return its future outcome} */
    static CompletableFuture<OpOutcome> start(Workspace ws, AgentId agent, String artifact, String op, Object... args) {
        CompletableFuture<OpOutcome> outcome = new CompletableFuture<>();
        ws.execOp(agent, OpTarget.name(artifact), op, args, outcome::complete);
        return outcome;
    }

    /** {@return the outcome of an operation, waiting up to 10 s (a safety net, not a timing assumption)} */
    static OpOutcome call(Workspace ws, AgentId agent, String artifact, String op, Object... args) {
        try {
            return start(ws, agent, artifact, op, args).get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            throw new AssertionError(op + " did not complete", e);
        }
    }

    /** {@return the success of an operation that must succeed} */
    static OpOutcome.Success ok(Workspace ws, AgentId agent, String artifact, String op, Object... args) {
        OpOutcome outcome = call(ws, agent, artifact, op, args);
        assertTrue(outcome.succeeded(), () -> agent.name() + ": " + op + " failed: " + outcome);
        return (OpOutcome.Success) outcome;
    }

    /** Asserts that an operation fails with the reason {@code reason(args...)}. */
    static void fails(String reason, List<Object> args, Workspace ws, AgentId agent, String artifact, String op, Object... opArgs) {
        OpOutcome outcome = call(ws, agent, artifact, op, opArgs);
        assertFalse(outcome.succeeded(), () -> agent.name() + ": " + op + " should have failed");
        OpOutcome.Failure f = (OpOutcome.Failure) outcome;
        assertEquals(reason, f.reasonFunctor(), f::toString);
        assertEquals(args, f.reasonArgs(), f::toString);
    }

    /** Joins an agent called {@code agent} that focuses {@code artifact}; {@return what it perceives} */
    static Watcher watch(Workspace ws, String agent, String artifact) {
        Watcher sees = new Watcher();
        ok(ws, ws.join(agent, sees), "body_" + agent, "focus", artifact);
        return sees;
    }

    /** What an agent focusing an artifact perceives: its properties now, and the signals so far. */
    static class Watcher extends ArtifactObserverAdapter {
        final List<PropertySnapshot> properties = new ArrayList<>();
        final List<String> signals = new ArrayList<>();

        @Override
        public synchronized void focused(ArtifactId artifact, List<PropertySnapshot> now) {
            properties.addAll(now);
            changed();
        }

        @Override
        public synchronized void propertyAdded(ArtifactId artifact, PropertySnapshot p) {
            properties.add(p);
            changed();
        }

        @Override
        public synchronized void propertyUpdated(ArtifactId artifact, PropertySnapshot old, PropertySnapshot now) {
            properties.set(properties.indexOf(old), now);
            changed();
        }

        @Override
        public synchronized void propertyRemoved(ArtifactId artifact, PropertySnapshot p) {
            properties.remove(p);
            changed();
        }

        @Override
        public synchronized void signalled(ArtifactId artifact, String type, List<Object> args) {
            signals.add(type + args);
        }

        /** Called after each change, holding the watcher: a test checks an invariant here. */
        void changed() {
        }

        /** {@return the values of the properties called {@code name}, in the order perceived} */
        synchronized List<List<Object>> values(String name) {
            return properties.stream().filter(p -> p.name().equals(name)).map(PropertySnapshot::values).toList();
        }
    }
}
