package jacabot.sim.device;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.geom.Pose;
import jacabot.sim.SimWorld;
import jacabot.sim.TestWorlds;
import jacabot.sim.robot.Robot;
import org.junit.jupiter.api.Test;

/** The Khepera at the origin facing north; a cylinder 5 cm ahead lies between its fingers. */
class GripperTest {
    private static SimWorld withCylinderAt(double x, double z) {
        return TestWorlds.khepera(0, 0, 0, "\"cylinders\": [{\"id\": \"red1\", \"x\": " + x + ", \"z\": " + z + "}]");
    }

    private static Gripper lowerAndClose(SimWorld w) {
        Gripper g = w.robot("k").getGripper();
        g.enableForceFeedback(40);
        g.enablePresence(40);
        g.armDown();
        w.step(1000);
        assertTrue(g.isArmDown());
        g.closeGrip();
        w.step(520);
        return g;
    }

    @Test
    void theArmTakesOneSecondAndTheFingersHalfASecond() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = w.robot("k").getGripper();
        g.armDown();
        w.step(480);
        assertEquals(0.48, g.getArmPosition(), 1e-9);
        assertFalse(g.isArmDown());
        w.step(520);
        assertTrue(g.isArmDown());
        g.closeGrip();
        w.step(240);
        assertEquals(0.48, g.getGripPosition(), 1e-9);
    }

    @Test
    void closingOnACylinderBetweenTheFingersGraspsIt() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = lowerAndClose(w);
        assertEquals("red1", g.heldObject());
        assertEquals(-40.0, g.getForceFeedback());
        assertEquals(1.0, g.getPresence());
        assertTrue(g.getForceFeedback() > -500 && g.getForceFeedback() < -5, "the thesis' grasp test");
    }

    @Test
    void aGraspedCylinderIsLiftedAndCarried() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = lowerAndClose(w);
        g.armUp();
        w.step(1000);
        assertTrue(g.isArmUp());
        Robot k = w.robot("k");
        k.setSpeeds(50, 100);
        w.step(3000);
        Pose p = k.pose();
        Pose c = w.supervisor().pose("red1");
        assertEquals(p.x() + 0.05 * Math.cos(Math.toRadians(p.heading())), c.x(), 1e-9);
        assertEquals(p.z() + 0.05 * Math.sin(Math.toRadians(p.heading())), c.z(), 1e-9);
        assertEquals("red1", w.supervisor().carried("k"));
    }

    @Test
    void aCylinderBesideTheFingersIsNotGrasped() {
        SimWorld w = withCylinderAt(0.05, 0.03);
        Gripper g = lowerAndClose(w);
        assertNull(g.heldObject());
        assertEquals(0.0, g.getForceFeedback());
        assertEquals(0.0, g.getPresence());
        assertEquals(1.0, g.getGripPosition());
    }

    @Test
    void closingWithTheArmUpGraspsNothing() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = w.robot("k").getGripper();
        g.enableForceFeedback(40);
        g.closeGrip();
        w.step(600);
        g.armDown();
        w.step(1000);
        assertNull(g.heldObject());
        assertEquals(0.0, g.getForceFeedback());
    }

    @Test
    void presenceSeesACylinderBetweenTheLoweredOpenFingers() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = w.robot("k").getGripper();
        g.enablePresence(40);
        w.step();
        assertEquals(0.0, g.getPresence());
        g.armDown();
        w.step(1000);
        assertEquals(1.0, g.getPresence());
    }

    @Test
    void knockingTheCarriedCylinderDropsTheForce() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = lowerAndClose(w);
        g.armUp();
        w.step(1000);
        assertTrue(w.supervisor().knockCarried("k"));
        w.step();
        assertNull(g.heldObject());
        assertEquals(0.0, g.getForceFeedback());
        assertEquals(0.0, g.getPresence());
        Pose c = w.supervisor().pose("red1");
        assertEquals(0.0285 + 0.0125 + 0.02, c.z(), 1e-3); // thrown to the robot's right (east)
        assertFalse(w.supervisor().knockCarried("k"));
    }

    @Test
    void openingTheFingersSetsTheCylinderDown() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = lowerAndClose(w);
        g.openGrip();
        w.step(40);
        assertNull(g.heldObject());
        assertEquals(0.05, w.supervisor().pose("red1").x(), 1e-6);
        w.step(40);
        assertEquals(0.0, g.getForceFeedback());
    }

    @Test
    void aCarriedCylinderIsInvisibleToTheRobotsOwnSensors() {
        SimWorld w = withCylinderAt(0.05, 0);
        Gripper g = lowerAndClose(w);
        DistanceSensor front = w.robot("k").getDistanceSensor("front");
        front.enable(40);
        w.step();
        assertEquals(0.0, front.getValue());
        assertEquals(0.0, w.robot("k").contactTime());
        assertEquals("red1", g.heldObject());
    }
}
