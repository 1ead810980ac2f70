package jacabot.experiments;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.cartago.AgentId;
import jacabot.cartago.ArtifactId;
import jacabot.cartago.ArtifactObserverAdapter;
import jacabot.cartago.OpOutcome;
import jacabot.cartago.OpTarget;
import jacabot.cartago.PropertySnapshot;
import jacabot.cartago.Workspace;
import jacabot.robot.link.Command;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * One robot, two agents (the thesis' Chapter 6 wish): the middleware lends the wheels to one agent
 * at a time and refuses the others' wheel commands with a reason; one driver per control step.
 */
class WheelLeaseTest {
    @Test
    void anyAgentDrivesUntilOneTakesTheWheelsThenOnlyTheHolder() {
        var lease = new WheelLease();
        assertEquals(Optional.empty(), lease.command("task"));
        lease.endStep();
        assertEquals(Optional.empty(), lease.command("energy"), "nobody has taken them: one agent per robot, as in the thesis");
        lease.endStep();
        lease.hold("task");
        assertEquals(Optional.empty(), lease.command("task"));
        assertEquals(Optional.of("task holds the wheels"), lease.command("energy"));
        assertFalse(lease.isFreeFor("energy"));
        assertThrows(IllegalStateException.class, () -> lease.hold("energy"));
        assertFalse(lease.release("energy"), "only the holder lets them go");
        assertTrue(lease.release("task"));
        assertTrue(lease.command("task").isPresent(), "released: nobody drives until an agent takes them again");
        assertEquals(2, lease.refusals());
    }

    @Test
    void oneDriverPerControlStepAndTheWheelsChangeHandsAtItsEnd() {
        var lease = new WheelLease();
        lease.endStep(); // the runner marks steps
        assertEquals(Optional.empty(), lease.command("task"));
        assertEquals(Optional.of("task has driven the wheels in this control step"), lease.command("energy"));
        lease.hold("task");
        lease.command("task"); // the task stops the robot, then lets the wheels go
        lease.release("task");
        assertFalse(lease.isFreeFor("energy"), "not in the step the task drove in");
        assertEquals(List.of("task"), lease.endStep());
        assertTrue(lease.isFreeFor("energy"));
        lease.hold("energy");
        assertEquals(Optional.empty(), lease.command("energy"));
        assertEquals(List.of("energy"), lease.endStep());
        assertEquals(Map.of("task", 1L, "energy", 1L), lease.stepsDriven());
        assertEquals(0, lease.stepsWithTwoDrivers());
    }

    /** Two agents on one middleware artifact, stepped as the lockstep runner steps it. */
    private static final class SharedRobot {
        final Workspace ws = Workspace.builder("main").stepped().build();
        final Map<String, Object> properties = new HashMap<>();
        final AgentId task = ws.join("task", new ArtifactObserverAdapter());
        final AgentId energy;
        final ArtifactId id;
        final MiddlewareArtifact middleware;

        SharedRobot() throws Exception {
            energy = ws.join("energy", new ArtifactObserverAdapter() {
                @Override
                public void focused(ArtifactId a, List<PropertySnapshot> ps) {
                    ps.forEach(p -> properties.put(p.name(), p.value()));
                }

                @Override
                public void propertyAdded(ArtifactId a, PropertySnapshot p) {
                    properties.put(p.name(), p.value());
                }

                @Override
                public void propertyUpdated(ArtifactId a, PropertySnapshot old, PropertySnapshot now) {
                    properties.put(now.name(), now.value());
                }
            });
            id = ws.createArtifact("middleware", SuspendResumeMiddleware.class.getName(), 0, "lockstep");
            middleware = ws.artifactObject(id, MiddlewareArtifact.class).orElseThrow();
            start(energy, "focus", id);
            ws.runPending();
        }

        /** Starts an operation; {@return its outcome once the workspace is idle (null: it still waits)} */
        OpOutcome[] start(AgentId agent, String op, Object... args) {
            var outcome = new OpOutcome[1];
            ws.execOp(agent, op.equals("focus") ? OpTarget.any() : OpTarget.id(id), op, args, o -> outcome[0] = o);
            ws.runPending();
            return outcome;
        }
    }

    @Test
    void theMiddlewareRefusesTheWheelsToAnAgentThatDoesNotHoldThem() throws Exception {
        var robot = new SharedRobot();
        assertTrue(robot.start(robot.task, "acquireWheels")[0] instanceof OpOutcome.Success);
        assertEquals("task", String.valueOf(robot.properties.get("wheels")));
        assertTrue(robot.start(robot.task, "setSpeeds", 50.0, 50.0)[0] instanceof OpOutcome.Success);
        var refused = robot.start(robot.energy, "stop")[0];
        assertTrue(refused instanceof OpOutcome.Failure f && f.reasonFunctor().equals("wheels_held_by")
                && f.message().contains("task holds the wheels"), String.valueOf(refused));
        assertEquals(List.of(Command.setSpeeds(50, 50)), robot.middleware.takeCommands(), "the energy agent's stop never left");

        // the energy agent waits for the wheels; the task stops the robot and lets them go
        var waiting = robot.start(robot.energy, "acquireWheels");
        assertNull(waiting[0]);
        robot.start(robot.task, "stop");
        robot.start(robot.task, "releaseWheels");
        assertNull(waiting[0], "the wheels change hands at the step's end");
        assertEquals(List.of(Command.stop()), robot.middleware.takeCommands());
        robot.ws.runPending();
        assertTrue(waiting[0] instanceof OpOutcome.Success, String.valueOf(waiting[0]));
        assertEquals("energy", String.valueOf(robot.properties.get("wheels")));
        assertTrue(robot.start(robot.task, "forward")[0] instanceof OpOutcome.Failure);
        assertTrue(robot.start(robot.energy, "forward")[0] instanceof OpOutcome.Success);
        robot.start(robot.energy, "releaseWheels");
        assertEquals(MiddlewareArtifact.Wheels.FREE.name().toLowerCase(), String.valueOf(robot.properties.get("wheels")).toLowerCase());
        var nobody = robot.start(robot.task, "stop")[0];
        assertTrue(nobody instanceof OpOutcome.Failure f && f.reasonFunctor().equals("wheels_not_held"), String.valueOf(nobody));
        robot.ws.close();
    }
}
