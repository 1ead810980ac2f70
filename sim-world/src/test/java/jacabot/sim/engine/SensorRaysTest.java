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
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Vector2;
import org.junit.jupiter.api.Test;

/**
 * The world's rays give what dyn4j's casts give, object by object (the sensors' readings before
 * the closed-form circles, the allocation-free GJK and the new broad phases): the same objects,
 * distances to the bit and order, from random poses in a cluttered arena with turned boxes, rays
 * along walls and objects pressed against the origin included.
 */
class SensorRaysTest {
    /** What the sensors' rays were: every object's fixtures cast by dyn4j, nearest first (stable). */
    private static List<RayHit> dyn4j(Physics physics, SimObject self, Vec2 origin, double bearingDeg, double range) {
        double r = Math.toRadians(bearingDeg);
        Ray ray = new Ray(new Vector2(origin.x() - Physics.BACKOFF * Math.cos(r), origin.z() - Physics.BACKOFF * Math.sin(r)), r);
        Gjk gjk = new Gjk();
        List<RayHit> hits = new ArrayList<>();
        for (SimObject o : physics.objects()) {
            if (o == self || o.carriedBy != null) {
                continue;
            }
            for (BodyFixture f : o.body.getFixtures()) {
                Raycast result = new Raycast();
                if (gjk.raycast(ray, range + Physics.BACKOFF, f.getShape(), o.body.getTransform(), result)) {
                    double d = Math.max(0, result.getDistance() - Physics.BACKOFF);
                    if (d <= range) {
                        hits.add(new RayHit(d, o.color, o.height, o.id, o.reflectance));
                    }
                }
            }
        }
        hits.sort(Comparator.comparingDouble(RayHit::distance));
        return hits;
    }

    @Test
    void theRaysSeeWhatDyn4jsCastsSee() {
        var rnd = new Random(5);
        Physics physics = new Physics(8);
        physics.addArenaWalls(new ArenaSpec(2, 2, 0.02, 0.1, new Rgb(200, 200, 200), new Rgb(90, 90, 90)));
        for (int i = 0; i < 40; i++) {
            double x = rnd.nextDouble() * 1.8 - 0.9, z = rnd.nextDouble() * 1.8 - 0.9;
            if (i % 3 == 0) {
                physics.addCylinder(new CylinderSpec("c" + i, x, z, 0.01 + rnd.nextDouble() * 0.03, 0.05, 0.1, new Rgb(255, 0, 0)));
            } else {
                physics.addBox(new BoxSpec("b" + i, x, z, 0.02 + rnd.nextDouble() * 0.2, 0.02 + rnd.nextDouble() * 0.2,
                        i % 2 == 0 ? 0 : rnd.nextDouble() * 360, 0.05, i % 4 == 1, 0.2, new Rgb(0, 0, 255)), ObjectKind.BOX);
            }
        }
        SimObject robot = physics.addRobot("k", 0.035, 0.05, new Rgb(0, 255, 0), 0.9, 0, 0, 0);
        RayCaster caster = physics.rayCaster(robot);
        int hits = 0, turnedBoxHits = 0;
        for (int pose = 0; pose < 300; pose++) {
            Vec2 origin = new Vec2(rnd.nextDouble() * 1.96 - 0.98, rnd.nextDouble() * 1.96 - 0.98);
            double heading = pose % 10 == 0 ? 90 * rnd.nextInt(4) : rnd.nextDouble() * 720 - 360; // some along the walls
            double[] bearings = new double[64];
            for (int c = 0; c < 64; c++) {
                bearings[c] = heading - 30 + (c + 0.5) * 60 / 64;
            }
            double range = pose % 3 == 0 ? 0.06 : 1.5;
            List<List<RayHit>> fan = caster.castFan(origin, bearings, range);
            for (int c = 0; c < 64; c++) {
                List<RayHit> expected = dyn4j(physics, robot, origin, bearings[c], range);
                String where = "pose " + pose + " at " + origin + ", bearing " + bearings[c] + ", range " + range;
                assertEquals(expected, caster.castAll(origin, bearings[c], range), where);
                assertEquals(expected, fan.get(c), where + " (fan)");
                hits += expected.size();
                for (RayHit h : expected) {
                    SimObject o = physics.get(h.objectId());
                    turnedBoxHits += o.kind == ObjectKind.BOX && o.body.getTransform().getRotationAngle() != 0 ? 1 : 0;
                }
            }
        }
        assertTrue(hits > 20_000 && turnedBoxHits > 1_000, hits + " hits, " + turnedBoxHits + " on turned boxes");
    }
}
