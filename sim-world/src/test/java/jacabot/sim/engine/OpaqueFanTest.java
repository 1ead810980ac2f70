package jacabot.sim.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jacabot.sim.device.Camera;
import jacabot.sim.device.RayCaster;
import jacabot.sim.device.RayHit;
import jacabot.sim.geom.Pose;
import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import java.util.List;
import java.util.Random;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;

/**
 * The cheap paths of the sensors' rays read what the plain ones read: a fan cast with an opaque
 * test ({@link RayCaster#castFan(Vec2, double[], double, Predicate)}, which skips what lies behind
 * an opaque hit) gives each ray the hits of {@link RayCaster#castAll} up to its first opaque one,
 * and the camera, which renders from it column by column, the image of the plain per-pixel
 * rendering over every hit; on random poses in random cluttered worlds, objects of every height.
 */
class OpaqueFanTest {
    private static final Rgb FLOOR = new Rgb(90, 90, 90), BACKGROUND = new Rgb(0, 0, 0);

    private static Physics clutteredWorld(Random rnd, double side) {
        Physics physics = new Physics(8);
        physics.addArenaWalls(new ArenaSpec(side, side, 0.02, 0.05 + rnd.nextDouble() * 0.1, FLOOR, new Rgb(200, 200, 200)));
        int objects = 5 + rnd.nextInt(40);
        for (int i = 0; i < objects; i++) {
            double x = (rnd.nextDouble() - 0.5) * (side - 0.2), z = (rnd.nextDouble() - 0.5) * (side - 0.2);
            double height = 0.01 + rnd.nextDouble() * 0.12;
            Rgb color = new Rgb(rnd.nextInt(256), rnd.nextInt(256), rnd.nextInt(256));
            if (i % 3 == 0) {
                physics.addCylinder(new CylinderSpec("c" + i, x, z, 0.01 + rnd.nextDouble() * 0.03, height, 0.1, color));
            } else {
                physics.addBox(new BoxSpec("b" + i, x, z, 0.02 + rnd.nextDouble() * 0.2, 0.02 + rnd.nextDouble() * 0.2,
                        rnd.nextDouble() * 360, height, i % 2 == 0, 0.2, color), ObjectKind.BOX);
            }
        }
        return physics;
    }

    /** {@return the hits up to and including the first that {@code opaque} accepts} */
    private static List<RayHit> upToOpaque(List<RayHit> hits, Predicate<RayHit> opaque) {
        for (int i = 0; i < hits.size(); i++) {
            if (opaque.test(hits.get(i))) {
                return hits.subList(0, i + 1);
            }
        }
        return hits;
    }

    /** A cluttered world of a random side with a robot in it: the side and the robot's ray caster. */
    private record Scene(double side, RayCaster caster) {
        static Scene random(Random rnd) {
            double side = 0.7 + rnd.nextDouble() * 3.3;
            Physics physics = clutteredWorld(rnd, side);
            SimObject robot = physics.addRobot("k", 0.0285, 0.03, new Rgb(0, 255, 0), 0.9, 0, 0, 0);
            return new Scene(side, physics.rayCaster(robot));
        }
    }

    @Test
    void aFanWithAnOpaqueTestGivesEachRaysHitsUpToItsFirstOpaqueOne() {
        var rnd = new Random(7);
        int opaqueSeen = 0, leftOut = 0;
        for (int world = 0; world < 20; world++) {
            Scene scene = Scene.random(rnd);
            double side = scene.side();
            RayCaster caster = scene.caster();
            for (int pose = 0; pose < 60; pose++) {
                Vec2 origin = new Vec2((rnd.nextDouble() - 0.5) * side, (rnd.nextDouble() - 0.5) * side);
                double heading = rnd.nextDouble() * 1440 - 720;
                int rays = pose % 3 == 0 ? 3 : 64;
                double[] bearings = new double[rays];
                for (int c = 0; c < rays; c++) {
                    bearings[c] = heading - 30 + (c + 0.5) * 60 / rays;
                }
                double range = pose % 4 == 0 ? 0.2 : 1.5, tall = rnd.nextDouble() * 0.1;
                Predicate<RayHit> opaque = pose % 5 == 0 ? hit -> true : hit -> hit.height() > tall + hit.distance() * 0.05;
                List<List<RayHit>> fan = caster.castFan(origin, bearings, range, opaque);
                for (int c = 0; c < rays; c++) {
                    List<RayHit> all = caster.castAll(origin, bearings[c], range), cheap = fan.get(c);
                    String where = "world " + world + ", pose " + pose + " at " + origin + ", ray " + c;
                    assertEquals(upToOpaque(all, opaque), upToOpaque(cheap, opaque), where);
                    assertTrue(all.containsAll(cheap), where + ": only hits of the ray");
                    opaqueSeen += upToOpaque(all, opaque).size() < all.size() ? 1 : 0;
                    leftOut += all.size() - cheap.size();
                }
            }
        }
        assertTrue(opaqueSeen > 3_000, opaqueSeen + " rays had hits behind an opaque one");
        assertTrue(leftOut > 3_000, leftOut + " hits behind opaque ones were left out");
    }

    @Test
    void theCameraRendersThePlainPerPixelImage() {
        var rnd = new Random(11);
        int pixels = 0, colours = 0;
        for (int world = 0; world < 20; world++) {
            Scene scene = Scene.random(rnd);
            double side = scene.side();
            RayCaster caster = scene.caster();
            Pose[] mount = new Pose[1];
            int width = 16 + rnd.nextInt(60), height = 1 + rnd.nextInt(12);
            double fov = 20 + rnd.nextDouble() * 100, lens = 0.01 + rnd.nextDouble() * 0.05, range = 0.3 + rnd.nextDouble() * 2;
            Camera camera = new Camera("camera", () -> 0, width, height, fov, lens, range, () -> mount[0], caster, FLOOR, BACKGROUND);
            for (int pose = 0; pose < 40; pose++) {
                mount[0] = new Pose((rnd.nextDouble() - 0.5) * side, (rnd.nextDouble() - 0.5) * side, rnd.nextDouble() * 1440 - 720);
                int[] plain = plainImage(caster, mount[0], width, height, fov, lens, range);
                assertArrayEquals(plain, camera.render(), "world " + world + ", pose " + mount[0]);
                for (int p : plain) {
                    pixels++;
                    colours += p != FLOOR.packed() && p != BACKGROUND.packed() ? 1 : 0;
                }
            }
        }
        assertTrue(colours > pixels / 10, colours + " of " + pixels + " pixels saw an object");
    }

    /** The camera's rendering as it was: each pixel walks its column's hits, every hit cast. */
    private static int[] plainImage(RayCaster caster, Pose p, int width, int height, double fov, double lens, double range) {
        double vfov = fov * height / width;
        int[] img = new int[width * height];
        for (int c = 0; c < width; c++) {
            List<RayHit> hits = caster.castAll(p.position(), p.heading() - fov / 2 + (c + 0.5) * fov / width, range);
            for (int r = 0; r < height; r++) {
                double slope = Math.tan(Math.toRadians(vfov / 2 - (r + 0.5) * vfov / height));
                img[r * width + c] = pixel(hits, slope, lens, range).packed();
            }
        }
        return img;
    }

    private static Rgb pixel(List<RayHit> hits, double slope, double lens, double range) {
        for (RayHit h : hits) {
            double y = lens + h.distance() * slope;
            if (y < 0) {
                return FLOOR;
            }
            if (y <= h.height()) {
                return h.color();
            }
        }
        return slope < 0 && lens + range * slope < 0 ? FLOOR : BACKGROUND;
    }
}
