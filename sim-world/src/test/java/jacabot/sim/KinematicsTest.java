package jacabot.sim;
import jacabot.sim.engine.WorldListener;
import jacabot.sim.geom.Pose;
import jacabot.sim.robot.Robot;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class KinematicsTest {
    @Test
    void fullSpeedDrivesTheKheperaFiveCentimetresASecondNorth() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        w.robot("k").setSpeeds(100, 100);
        w.step(1000);
        Pose p = w.robot("k").pose();
        assertEquals(0.05, p.x(), 1e-9);
        assertEquals(0.0, p.z(), 1e-9);
        assertEquals(0.0, p.heading(), 1e-9);
        assertEquals(1000, w.timeMs());
    }

    @Test
    void leftWheelFasterTurnsRightAtTheDifferentialRate() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        w.robot("k").setSpeeds(50, -50);
        w.step(1000);
        double rate = Math.toDegrees(100 * 0.0005 / 0.053);
        Pose p = w.robot("k").pose();
        assertEquals(rate, p.heading(), 1e-6);
        assertEquals(0.0, p.x(), 1e-9);
    }

    @Test
    void speedsAreClampedToTheModelMaximum() {
        SimWorld w = TestWorlds.khepera(0, 0, 90, "");
        Robot k = w.robot("k");
        k.setSpeeds(500, 500);
        assertEquals(100, k.getWheels().getLeftSpeed());
        w.step(1000);
        assertEquals(0.05, k.pose().z(), 1e-9);
    }

    @Test
    void aWallStopsTheRobotAndCountsContactTime() {
        SimWorld w = TestWorlds.khepera(0.45, 0, 0, "");
        Robot k = w.robot("k");
        k.setSpeeds(100, 100);
        w.step(4000);
        assertEquals(0.5 - 0.0285, k.pose().x(), 0.003);
        assertTrue(k.contactTime() > 2.5 && k.contactTime() <= 4.0, "contact time " + k.contactTime());
        assertEquals(0.0, TestWorlds.khepera(0, 0, 0, "").robot("k").contactTime());
    }

    @Test
    void theTrajectoryHasOnePosePerControlStep() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        w.robot("k").setSpeeds(100, 100);
        for (int i = 0; i < 25; i++) {
            w.step();
        }
        assertEquals(26, w.robot("k").trajectory().size());
        assertEquals(0.05, w.robot("k").trajectory().get(25).x(), 1e-9);
        assertEquals(0.002, w.robot("k").trajectory().get(1).x(), 1e-12);
    }

    @Test
    void aLongTrajectoryIsThinnedToEverySecondPoseAndKeepsTheLatest() {
        SimWorld w = TestWorlds.khepera(0, 0, 0, "");
        w.robot("k").setSpeeds(20, -10);
        List<Pose> every = new ArrayList<>(List.of(w.robot("k").pose()));
        w.addListener(new WorldListener() {
            @Override
            public void controlStepEnded(long timeMs) {
                every.add(w.robot("k").pose());
            }
        });
        int limit = 1 << 15, steps = 2 * limit + 3;
        for (int i = 0; i < steps; i++) {
            w.step();
        }
        var t = w.robot("k").trajectory();
        assertTrue(t.size() <= limit + 1, t.size() + " poses");
        assertEquals(limit / 2 + 2, t.size(), "every 4th of 65,539 steps, then the latest");
        for (int j = 0; j < t.size() - 1; j++) {
            assertEquals(every.get(4 * j), t.get(j), "pose " + j);
        }
        assertEquals(w.robot("k").pose(), t.get(t.size() - 1));
    }
}
