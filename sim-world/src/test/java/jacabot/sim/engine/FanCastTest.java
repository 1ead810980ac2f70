package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.RayCaster;
import jacabot.sim.device.RayHit;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A camera's fan of rays ({@link RayCaster#castFan}, with its shared broad phase) sees exactly what
 * its rays see one by one ({@link RayCaster#castAll}): same objects, same distances to the bit, same
 * order, from random poses in a cluttered arena, objects pressed against the lens included.
 */
class FanCastTest {
    @Test
    void aFanSeesWhatItsRaysSeeOneByOne() {
        var rnd = new Random(42);
        Physics physics = new Physics(8);
        physics.addArenaWalls(new ArenaSpec(3, 3, 0.02, 0.1, new Rgb(200, 200, 200), new Rgb(90, 90, 90)));
        for (int i = 0; i < 60; i++) {
            double x = rnd.nextDouble() * 2.8 - 1.4, z = rnd.nextDouble() * 2.8 - 1.4;
            if (i % 3 == 0) {
                physics.addCylinder(new CylinderSpec("c" + i, x, z, 0.01 + rnd.nextDouble() * 0.03, 0.05, 0.1, new Rgb(255, 0, 0)));
            } else {
                physics.addBox(new BoxSpec("b" + i, x, z, 0.02 + rnd.nextDouble() * 0.2, 0.02 + rnd.nextDouble() * 0.2,
                        rnd.nextDouble() * 360, 0.05, i % 2 == 0, 0.2, new Rgb(0, 0, 255)), ObjectKind.BOX);
            }
        }
        SimObject robot = physics.addRobot("k", 0.035, 0.05, new Rgb(0, 255, 0), 0.9, 0, 0, 0);
        RayCaster caster = physics.rayCaster(robot);
        int hitsSeen = 0, nearHits = 0;
        for (int pose = 0; pose < 400; pose++) {
            Vec2 origin = new Vec2(rnd.nextDouble() * 2.9 - 1.45, rnd.nextDouble() * 2.9 - 1.45);
            double heading = rnd.nextDouble() * 1440 - 720; // any turn count, as the compass' heading grows
            double[] bearings = new double[64];
            for (int c = 0; c < 64; c++) {
                bearings[c] = heading - 30 + (c + 0.5) * 60 / 64;
            }
            double range = pose % 4 == 0 ? 0.2 : 1.5;
            List<List<RayHit>> fan = caster.castFan(origin, bearings, range);
            for (int c = 0; c < 64; c++) {
                List<RayHit> one = caster.castAll(origin, bearings[c], range);
                assertEquals(one, fan.get(c), "pose " + pose + " at " + origin + ", column " + c);
                hitsSeen += one.size();
                nearHits += one.isEmpty() || one.get(0).distance() > 0.005 ? 0 : 1;
            }
        }
        assertTrue(hitsSeen > 10_000, hitsSeen + " hits: the rays saw the clutter");
        assertTrue(nearHits > 0, "some rays started inside or against an object");
    }
}
