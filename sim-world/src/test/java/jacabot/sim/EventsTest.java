package jacabot.sim;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Pose;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.Gripper;
import jacabot.sim.world.BoxSpec;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Each kind of scripted event, and the supervisor's counterparts. */
class EventsTest {
    static final String BOX = "\"boxes\": [{\"id\": \"b\", \"x\": 0.3, \"z\": 0.3, \"size\": 0.06}]";
    static final String CYL = "\"cylinders\": [{\"id\": \"red1\", \"x\": 0.05, \"z\": 0}]";

    private static boolean exists(SimWorld w, String id) {
        return w.supervisor().objects().stream().anyMatch(o -> o.id().equals(id));
    }

    @Test
    void moveAtATime() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, BOX + ", \"events\": [{\"at\": 1.0, \"do\": \"move\", \"object\": \"b\", \"x\": -0.3, \"z\": 0.2, \"heading\": 45}]");
        w.step(960);
        assertEquals(0.3, w.supervisor().pose("b").x(), 1e-12);
        w.step();
        Pose p = w.supervisor().pose("b");
        assertEquals(-0.3, p.x(), 1e-12);
        assertEquals(0.2, p.z(), 1e-12);
        assertEquals(45, p.heading(), 1e-9);
        assertEquals(0, w.pendingEvents());
    }

    @Test
    void addAndRemoveAtTimes() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, BOX + ", \"events\": ["
                + "{\"at\": 0.5, \"do\": \"add\", \"cylinder\": {\"id\": \"red2\", \"x\": -0.2, \"z\": 0.2}},"
                + "{\"at\": 0.5, \"do\": \"add\", \"box\": {\"id\": \"b2\", \"x\": -0.2, \"z\": -0.2, \"size\": 0.05}},"
                + "{\"at\": 1.0, \"do\": \"remove\", \"object\": \"b\"},"
                + "{\"at\": 1.5, \"do\": \"remove\", \"object\": \"red2\"}]");
        List<String> log = new ArrayList<>();
        w.addListener(new WorldListener() {
            @Override
            public void eventFired(long timeMs, String description) {
                log.add(timeMs + " " + description);
            }
        });
        w.step(480);
        assertFalse(exists(w, "red2"));
        w.step(40);
        assertTrue(exists(w, "red2") && exists(w, "b2"));
        w.step(520);
        assertFalse(exists(w, "b"));
        w.step(480);
        assertFalse(exists(w, "red2"));
        assertEquals(List.of("504 added cylinder 'red2'", "504 added box 'b2'", "1000 removed 'b'", "1504 removed 'red2'"), log);
    }

    @Test
    void moveTheCylinderAwayAfterTheRobotComesNear() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"cylinders\": [{\"id\": \"red1\", \"x\": 0.15, \"z\": 0}],"
                + "\"events\": [{\"when\": {\"robot\": \"k\", \"near\": \"red1\", \"within\": 0.071}, \"after\": 0.2,"
                + " \"do\": \"move\", \"object\": \"red1\", \"x\": -0.3, \"z\": -0.3}]");
        w.robot("k").setSpeeds(100, 100); // 5 cm/s: within 7.1 cm at 1.584 s, moved 0.2 s later
        w.step(1560);
        assertEquals(0.15, w.supervisor().pose("red1").x(), 1e-12);
        w.step(40);
        w.step(160);
        assertEquals(0.15, w.supervisor().pose("red1").x(), 1e-12);
        w.step(40);
        assertEquals(-0.3, w.supervisor().pose("red1").x(), 1e-12);
    }

    @Test
    void knockTheCarriedCylinder() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, CYL + ", \"events\": [{\"at\": 3, \"do\": \"knock\", \"robot\": \"k\"}]");
        Gripper g = w.robot("k").getGripper();
        g.armDown();
        w.step(1000);
        g.closeGrip();
        w.step(1000);
        assertEquals("red1", g.heldObject());
        w.step(1000);
        assertNull(g.heldObject());
        assertNull(w.supervisor().carried("k"));
    }

    @Test
    void knockWithNothingCarriedIsReportedNotThrown() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"events\": [{\"at\": 0.04, \"do\": \"knock\", \"robot\": \"k\"}]");
        List<String> failures = new ArrayList<>();
        w.addListener(new WorldListener() {
            @Override
            public void eventFailed(long timeMs, String description, String reason) {
                failures.add(reason);
            }
        });
        w.step();
        assertEquals(List.of("robot 'k' carries nothing"), failures);
    }

    @Test
    void drainTheBattery() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"events\": [{\"at\": 1, \"do\": \"drain\", \"robot\": \"k\", \"amount\": 300}]");
        w.step(2000);
        assertEquals(1000 - 300 - 0.5 * 2, w.robot("k").getBattery().energy(), 1e-9);
    }

    @Test
    void theSupervisorMovesAddsAndRemoves() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, CYL);
        Supervisor s = w.supervisor();
        s.move("k", 0.2, -0.2, 90);
        assertEquals(new Pose(0.2, -0.2, 90), s.pose("k"));
        s.addBox(new BoxSpec("nb", -0.3, 0, 0.05, 0.05, 0, 0.05, true, 0.2, Rgb.WHITE));
        assertTrue(exists(w, "nb"));
        assertThrows(IllegalArgumentException.class, () -> s.addBox(new BoxSpec("nb", 0, 0, 0.05, 0.05, 0, 0.05, false, 0, Rgb.WHITE)));
        assertTrue(s.remove("nb"));
        assertFalse(s.remove("nb"));
        assertThrows(IllegalArgumentException.class, () -> s.remove("wall-north"));
        assertThrows(IllegalArgumentException.class, () -> s.pose("nothing"));
        assertEquals(4 + 1 + 1, s.objects().size()); // walls, cylinder, robot
    }

    @Test
    void aRobotPushesAMovableBoxButNotAFixedOne() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "\"boxes\": [{\"id\": \"m\", \"x\": 0.08, \"z\": 0, \"size\": 0.05, \"movable\": true}]");
        w.robot("k").setSpeeds(100, 100);
        w.step(2000);
        assertTrue(w.supervisor().pose("m").x() > 0.12, "pushed: " + w.supervisor().pose("m"));
        assertTrue(w.robot("k").contactTime() > 1.0);
    }
}
