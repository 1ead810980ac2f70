package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.robot.Robot;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.BoxSpec;
import org.junit.jupiter.api.Test;

/**
 * Continuous collision detection only in a world where a body can be fast (Physics'
 * chooseContinuousDetection): a robot's world is stepped without it, and a robot driven into a
 * wall at full speed still stops at the wall.
 */
class ContinuousDetectionTest {
    private static Physics arena() {
        var physics = new Physics(8);
        physics.addArenaWalls(new ArenaSpec(1, 1, 0.02, 0.1, new Rgb(200, 200, 200), new Rgb(100, 100, 100)));
        return physics;
    }

    @Test
    void aKheperasWorldIsSteppedWithoutItAndAFastRobotsWithIt() {
        var slow = arena();
        slow.addRobot("k", 0.0285, 0.03, new Rgb(0, 255, 0), 0.9, 0.05, 0, 0, 0);
        assertFalse(slow.continuousDetection(), "5 cm/s: 0.4 mm a step against a 2 cm wall");

        var fast = arena();
        fast.addRobot("k", 0.0285, 0.03, new Rgb(0, 255, 0), 0.9, 2.0, 0, 0, 0);
        assertTrue(fast.continuousDetection(), "2 m/s: 16 mm a step, more than a quarter of the wall");
    }

    @Test
    void aThinObjectAddedTurnsItOnAndRemovedOffAgain() {
        var physics = arena();
        physics.addRobot("k", 0.0285, 0.03, new Rgb(0, 255, 0), 0.9, 0.05, 0, 0, 0);
        physics.addBox(new BoxSpec("sheet", 0.3, 0, 0.002, 0.3, 0, 0.05, false, 0, new Rgb(0, 0, 255)), ObjectKind.BOX);
        assertTrue(physics.continuousDetection(), "a 2 mm sheet: a pushed body could cross half of it in a step");
        physics.remove("sheet");
        assertFalse(physics.continuousDetection());
    }

    @Test
    void aRobotDrivenIntoAWallAtFullSpeedStopsThere() {
        SimWorld world = TestWorlds.khepera(0, 0, 0, ""); // heading north, +x, towards the wall at x = 0.5
        Robot k = world.robot("k");
        k.setSpeeds(100, 100);
        for (int i = 0; i < 500; i++) { // 20 s at 5 cm/s: 1 m, twice the way to the wall
            world.step();
            Pose p = k.pose();
            assertTrue(p.x() < 0.5 - 0.0285 + 0.002, "inside the wall at step " + i + ": " + p);
        }
        assertTrue(k.pose().x() > 0.5 - 0.0285 - 0.005, "it reached the wall: " + k.pose());
        assertTrue(k.contactTime() > 5, "it pressed against it: " + k.contactTime());
    }
}
