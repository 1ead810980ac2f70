package jacabot.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.DistanceSensor;
import jacabot.sim.device.Gripper;
import jacabot.sim.robot.Robot;
import org.junit.jupiter.api.Test;

/** The thesis' thresholds used the way its controllers use them. */
class ThesisThresholdsTest {
    @Test
    void stoppingWhenTheFrontSensorExceeds480LeavesTheCylinderBetweenTheFingers() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"cylinders\": [{\"id\": \"red1\", \"x\": 0.15, \"z\": 0.004}]");
        Robot k = w.robot("k");
        DistanceSensor front = k.getDistanceSensor("front");
        front.enable(40);
        k.setSpeeds(50, 50);
        while (!(front.getValue() > 480)) {
            w.step();
            assertTrue(w.time() < 10, "never got very close");
        }
        k.setSpeeds(0, 0);
        Gripper g = k.getGripper();
        g.enableForceFeedback(40);
        g.armDown();
        w.step(1000);
        g.closeGrip();
        w.step(600);
        double force = g.getForceFeedback();
        assertTrue(force > -500 && force < -5, "grasped: force " + force);
        assertEquals("red1", g.heldObject());
    }

    @Test
    void aWallOnOneSideGivesALeftRightDeltaOver100() {
        SimWorld w = TestWorlds.world("\"robots\": [{\"name\": \"m\", \"model\": \"mybot\", \"heading\": 30}],"
                + "\"walls\": [{\"x\": 0.2, \"z\": 0, \"size\": [0.1, 0.6]}]");
        Robot m = w.robot("m");
        DistanceSensor left = m.getDistanceSensor("left"), right = m.getDistanceSensor("right");
        left.enable(40);
        right.enable(40);
        w.step();
        // turned 30° east, the left sensor (10° east of north) faces the wall more squarely than the right (50°)
        assertTrue(left.getValue() - right.getValue() > 100, left.getValue() + " vs " + right.getValue());
        assertTrue(right.getValue() < 350);
    }

    @Test
    void unknownDevicesAreNamedInTheError() {
        Robot m = TestWorlds.world("\"robots\": [{\"name\": \"m\", \"model\": \"mybot\"}]").robot("m");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.getDistanceSensor("front"));
        assertTrue(e.getMessage().contains("[wheels, left, right]"), e.getMessage());
        assertThrows(IllegalArgumentException.class, m::getGripper);
    }
}
