package jacabot.sim.engine;

import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.device.RayCaster;
import jacabot.sim.device.RayHit;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.World;

/**
 * The dyn4j world: a top-down plane with no gravity, stepped at a fixed frequency. Floor friction
 * on movable objects is modelled by linear and angular damping. Internal to sim-world.
 */
final class Physics {
    /** Damping (1/s) standing in for floor friction on boxes and cylinders. */
    static final double FLOOR_DAMPING = 8.0;

    /** How far behind its origin a ray starts, in metres. */
    static final double BACKOFF = 0.01;

    /** How much the ray filter grows each bounding box, in metres: far above GJK's tolerance. */
    private static final double AABB_MARGIN = 1e-3;

    /** Radians added on each side of an object's angle in a fan's broad phase: far above rounding. */
    private static final double ANGLE_MARGIN = 1e-7;

    private final World<Body> world = new World<>();
    private final Map<String, SimObject> objects = new LinkedHashMap<>();

    Physics(int basicTimeStepMs) {
        world.setGravity(World.ZERO_GRAVITY);
        world.getSettings().setStepFrequency(basicTimeStepMs / 1000.0);
        world.getSettings().setAtRestDetectionEnabled(false);
    }

    void step() {
        world.step(1);
    }

    Collection<SimObject> objects() {
        return Collections.unmodifiableCollection(objects.values());
    }

    SimObject get(String id) {
        return objects.get(id);
    }

    boolean contains(String id) {
        return objects.containsKey(id);
    }

    void addArenaWalls(ArenaSpec a) {
        double t = a.wallThickness(), hx = a.halfWidth(), hz = a.halfDepth();
        addBox(new BoxSpec("wall-north", hx + t / 2, 0, t, a.depth() + 2 * t, 0, a.wallHeight(), false, 0, a.wallColor()), ObjectKind.WALL);
        addBox(new BoxSpec("wall-south", -hx - t / 2, 0, t, a.depth() + 2 * t, 0, a.wallHeight(), false, 0, a.wallColor()), ObjectKind.WALL);
        addBox(new BoxSpec("wall-east", 0, hz + t / 2, a.width(), t, 0, a.wallHeight(), false, 0, a.wallColor()), ObjectKind.WALL);
        addBox(new BoxSpec("wall-west", 0, -hz - t / 2, a.width(), t, 0, a.wallHeight(), false, 0, a.wallColor()), ObjectKind.WALL);
    }

    SimObject addBox(BoxSpec b, ObjectKind kind) {
        Body body = new Body();
        BodyFixture f = body.addFixture(Geometry.createRectangle(b.sizeX(), b.sizeZ()));
        if (b.movable()) {
            f.setDensity(b.mass() / (b.sizeX() * b.sizeZ()));
            body.setMass(MassType.NORMAL);
            body.setLinearDamping(FLOOR_DAMPING);
            body.setAngularDamping(FLOOR_DAMPING);
        } else {
            body.setMass(MassType.INFINITE);
        }
        return register(new SimObject(b.id(), kind, body, b.color(), b.height(), b.sizeX(), b.sizeZ(), b.movable()), b.x(), b.z(), b.heading());
    }

    SimObject addCylinder(CylinderSpec c) {
        Body body = new Body();
        BodyFixture f = body.addFixture(Geometry.createCircle(c.radius()));
        f.setDensity(c.mass() / (Math.PI * c.radius() * c.radius()));
        body.setMass(MassType.NORMAL);
        body.setLinearDamping(FLOOR_DAMPING);
        body.setAngularDamping(FLOOR_DAMPING);
        return register(new SimObject(c.id(), ObjectKind.CYLINDER, body, c.color(), c.height(), 2 * c.radius(), 2 * c.radius(), true),
                c.x(), c.z(), 0);
    }

    /**
     * A robot body: a disc whose rotation only the wheels change (infinite inertia), heavy enough
     * that pushing boxes and cylinders does not slow it, frictionless against walls.
     */
    SimObject addRobot(String name, double radius, double height, Rgb color, double x, double z, double heading) {
        Body body = new Body();
        BodyFixture f = body.addFixture(Geometry.createCircle(radius));
        f.setFriction(0);
        f.setDensity(50.0 / (Math.PI * radius * radius));
        body.setMass(MassType.FIXED_ANGULAR_VELOCITY);
        body.setLinearDamping(0);
        body.setAngularDamping(0); // dyn4j's default is not 0: the wheels alone set the velocities
        return register(new SimObject(name, ObjectKind.ROBOT, body, color, height, 2 * radius, 2 * radius, false), x, z, heading);
    }

    private SimObject register(SimObject o, double x, double z, double heading) {
        if (objects.containsKey(o.id)) {
            throw new IllegalArgumentException("an object named '" + o.id + "' already exists");
        }
        o.place(x, z, heading);
        objects.put(o.id, o);
        world.addBody(o.body);
        return o;
    }

    SimObject remove(String id) {
        SimObject o = objects.remove(id);
        if (o != null) {
            world.removeBody(o.body);
        }
        return o;
    }

    /** {@return whether the body touches a solid body (walls, objects, robots; ghosts excluded)} */
    boolean inContact(SimObject o) {
        return !world.getInContactBodies(o.body, false).isEmpty();
    }

    /** A ray caster that ignores one robot and every carried object. */
    RayCaster rayCaster(SimObject self) {
        return new RayCaster() {
            @Override
            public List<RayHit> castAll(Vec2 origin, double bearingDeg, double maxRange) {
                return Physics.this.castAll(self, origin, bearingDeg, maxRange);
            }

            @Override
            public List<List<RayHit>> castFan(Vec2 origin, double[] bearingsDeg, double maxRange) {
                return Physics.this.castFan(self, origin, bearingsDeg, maxRange);
            }
        };
    }

    /**
     * Rays start {@link #BACKOFF} behind their origin (inside the robot, which is ignored), so that an
     * object pressed against the sensor, slightly penetrating, is still seen, at distance 0.
     */
    private static Ray ray(Vec2 origin, double bearingDeg) {
        double r = Math.toRadians(bearingDeg);
        return new Ray(new Vector2(origin.x() - BACKOFF * Math.cos(r), origin.z() - BACKOFF * Math.sin(r)), r);
    }

    private List<RayHit> castAll(SimObject self, Vec2 origin, double bearingDeg, double maxRange) {
        Ray ray = ray(origin, bearingDeg);
        Raycast raycast = new Raycast();
        List<RayHit> hits = new ArrayList<>(4);
        for (SimObject o : objects.values()) {
            if (o != self && o.carriedBy == null) {
                cast(o, ray, maxRange, raycast, hits);
            }
        }
        hits.sort(Comparator.comparingDouble(RayHit::distance)); // stable: ties keep insertion order
        return hits;
    }

    /** Casts one ray against one object; a hit within range joins {@code hits}. */
    private void cast(SimObject o, Ray ray, double maxRange, Raycast raycast, List<RayHit> hits) {
        if (!mayCross(o.bounds(), ray, maxRange + BACKOFF)) {
            return;
        }
        double best = Double.POSITIVE_INFINITY;
        for (BodyFixture f : o.body.getFixtures()) {
            raycast.clear();
            if (world.getRaycastDetector().raycast(ray, maxRange + BACKOFF, f.getShape(), o.body.getTransform(), raycast)
                    && raycast.getDistance() - BACKOFF < best) {
                best = Math.max(0, raycast.getDistance() - BACKOFF);
            }
        }
        if (best <= maxRange) {
            hits.add(new RayHit(best, o.color, o.height, o.id));
        }
    }

    /**
     * A camera's rays, each with the result {@link #castAll} gives it, with a broad phase shared by
     * the fan: each object's box (grown by twice the ray filter's margin) is seen from the origin
     * under an angle, and a ray is tried only against the objects whose angle holds its bearing, in
     * the world's order. The filter is conservative (every point of a ray lies within
     * {@code maxRange + BACKOFF} of the origin, and its part behind the origin within {@code BACKOFF}),
     * so the rays meet the same objects in the same order as one by one: the image is the same, for
     * about a tenth of the casts (64 columns × every object before).
     */
    private List<List<RayHit>> castFan(SimObject self, Vec2 origin, double[] bearingsDeg, double maxRange) {
        int n = bearingsDeg.length;
        double ox = origin.x(), oz = origin.z();
        double[] bearing = new double[n];
        for (int k = 0; k < n; k++) {
            bearing[k] = Math.toRadians(bearingsDeg[k]);
        }
        List<List<SimObject>> reach = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            reach.add(new ArrayList<>());
        }
        double grow = 2 * AABB_MARGIN;
        for (SimObject o : objects.values()) {
            if (o == self || o.carriedBy != null) {
                continue;
            }
            AABB b = o.bounds();
            double minX = b.getMinX() - grow, maxX = b.getMaxX() + grow, minZ = b.getMinY() - grow, maxZ = b.getMaxY() + grow;
            double dx = Math.max(0, Math.max(minX - ox, ox - maxX)), dz = Math.max(0, Math.max(minZ - oz, oz - maxZ));
            double d = Math.sqrt(dx * dx + dz * dz);
            if (d > maxRange + BACKOFF) {
                continue; // out of every ray's reach
            }
            if (d <= BACKOFF + grow) {
                reach.forEach(r -> r.add(o)); // at the origin, or behind it within the back-off: every ray
                continue;
            }
            // the origin is outside the box: the directions to it span less than a half turn around its centre's
            double c = Math.atan2((minZ + maxZ) / 2 - oz, (minX + maxX) / 2 - ox);
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int corner = 0; corner < 4; corner++) {
                double a = Math.atan2(((corner & 1) == 0 ? minZ : maxZ) - oz, ((corner & 2) == 0 ? minX : maxX) - ox) - c;
                a = a > Math.PI ? a - 2 * Math.PI : a < -Math.PI ? a + 2 * Math.PI : a; // within a half turn of c
                lo = Math.min(lo, a);
                hi = Math.max(hi, a);
            }
            lo -= ANGLE_MARGIN;
            hi += ANGLE_MARGIN;
            for (int k = 0; k < n; k++) {
                double a = bearing[k] - c;
                a -= 2 * Math.PI * Math.rint(a / (2 * Math.PI)); // about [-pi, pi]; the test below also tries a +- 2 pi
                if (a >= lo && a <= hi || a + 2 * Math.PI <= hi || a - 2 * Math.PI >= lo) {
                    reach.get(k).add(o);
                }
            }
        }
        List<List<RayHit>> fan = new ArrayList<>(n);
        Raycast raycast = new Raycast();
        for (int k = 0; k < n; k++) {
            Ray ray = ray(origin, bearingsDeg[k]);
            List<RayHit> hits = new ArrayList<>(4);
            for (SimObject o : reach.get(k)) {
                cast(o, ray, maxRange, raycast, hits);
            }
            hits.sort(Comparator.comparingDouble(RayHit::distance)); // stable, as castAll's
            fan.add(hits);
        }
        return fan;
    }

    /**
     * The slab test of a ray segment against a box grown by {@link #AABB_MARGIN}: a cheap, conservative
     * filter (a miss here is a miss for the exact cast), so the casts' results do not change while
     * most of the GJK casts — each sensor ray against every object — are skipped.
     */
    private static boolean mayCross(AABB box, Ray ray, double length) {
        Vector2 o = ray.getStart(), d = ray.getDirectionVector();
        double[] t = {0, length};
        return clip(o.x, d.x, box.getMinX() - AABB_MARGIN, box.getMaxX() + AABB_MARGIN, t)
                && clip(o.y, d.y, box.getMinY() - AABB_MARGIN, box.getMaxY() + AABB_MARGIN, t);
    }

    /** Narrows the ray's interval {@code t} to one slab; {@return false when it becomes empty} */
    private static boolean clip(double start, double dir, double lo, double hi, double[] t) {
        if (Math.abs(dir) < 1e-12) {
            return start >= lo && start <= hi;
        }
        double t1 = (lo - start) / dir, t2 = (hi - start) / dir;
        t[0] = Math.max(t[0], Math.min(t1, t2));
        t[1] = Math.min(t[1], Math.max(t1, t2));
        return t[0] <= t[1];
    }
}
