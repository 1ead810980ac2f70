package jacabot.sim.engine;

import jacabot.sim.geom.Rgb;
import jacabot.sim.geom.Vec2;
import jacabot.sim.device.RayCaster;
import jacabot.sim.device.RayHit;
import jacabot.sim.world.ArenaSpec;
import jacabot.sim.world.BoxSpec;
import jacabot.sim.world.CylinderSpec;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.dyn4j.collision.narrowphase.Gjk;
import org.dyn4j.collision.narrowphase.Raycast;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.geometry.Circle;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Rectangle;
import org.dyn4j.geometry.Transform;
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

    /**
     * How far from a rectangle a ray may pass and still get a GJK cast, in metres: GJK answers a hit
     * once its point on the ray lies within {@code sqrt(DEFAULT_RAYCAST_EPSILON)} (0.12 mm) of a chord
     * of the rectangle, so a ray that passes farther misses for it too.
     */
    private static final double GJK_MARGIN = 1e-3;

    /** How much a fan's broad phase grows each bounding circle, in metres: more than the rectangles' margin. */
    private static final double REACH_MARGIN = 2 * GJK_MARGIN;

    private final World<Body> world = new Dyn4jWorld();
    private final Map<String, SimObject> objects = new LinkedHashMap<>();
    private final BeamDirections directions = new BeamDirections();

    Physics(int basicTimeStepMs) {
        world.setGravity(World.ZERO_GRAVITY);
        world.getSettings().setStepFrequency(basicTimeStepMs / 1000.0);
        world.getSettings().setAtRestDetectionEnabled(false);
        world.setTimeOfImpactDetector(new BoundedAdvancement());
        BroadPhases.install(world);
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
        Body body = new TrackedBody();
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
        Body body = new TrackedBody();
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
    SimObject addRobot(String name, double radius, double height, Rgb color, double reflectance, double x, double z, double heading) {
        Body body = new TrackedBody();
        BodyFixture f = body.addFixture(Geometry.createCircle(radius));
        f.setFriction(0);
        f.setDensity(50.0 / (Math.PI * radius * radius));
        body.setMass(MassType.FIXED_ANGULAR_VELOCITY);
        body.setLinearDamping(0);
        body.setAngularDamping(0); // dyn4j's default is not 0: the wheels alone set the velocities
        return register(new SimObject(name, ObjectKind.ROBOT, body, color, reflectance, height, 2 * radius, 2 * radius, false), x, z, heading);
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

    /** {@return whether the body touches another robot's body} */
    boolean touchesRobot(SimObject o) {
        for (Body b : world.getInContactBodies(o.body, false)) {
            if (b.getUserData() instanceof SimObject other && other != o && other.kind == ObjectKind.ROBOT) {
                return true;
            }
        }
        return false;
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
                return Physics.this.castFan(self, origin, bearingsDeg, maxRange, null);
            }

            @Override
            public List<List<RayHit>> castFan(Vec2 origin, double[] bearingsDeg, double maxRange, Predicate<RayHit> opaque) {
                return Physics.this.castFan(self, origin, bearingsDeg, maxRange, opaque);
            }
        };
    }

    /**
     * Rays start {@link #BACKOFF} behind their origin (inside the robot, which is ignored), so that an
     * object pressed against the sensor, slightly penetrating, is still seen, at distance 0. The start
     * and the unit direction are formed as dyn4j's {@code Ray} forms them ({@link BeamDirections#of}),
     * so that the distances are those of its casts to the bit.
     */
    private static final class Beam {
        double sx, sy, dx, dy, radians;
        private Ray ray;

        Beam(Vec2 origin, double bearingDeg, BeamDirections directions) {
            aim(origin, bearingDeg, directions);
        }

        /** A beam to {@link #aim} before use. */
        Beam() {
        }

        /** Points this beam along another bearing (a fan reuses one beam for all its rays). {@return this beam} */
        Beam aim(Vec2 origin, double bearingDeg, BeamDirections directions) {
            int at = directions.of(bearingDeg);
            double[] v = directions.values();
            radians = v[at + BeamDirections.RADIANS];
            sx = origin.x() - BACKOFF * v[at + BeamDirections.COS];
            sy = origin.z() - BACKOFF * v[at + BeamDirections.SIN];
            dx = v[at + BeamDirections.DX];
            dy = v[at + BeamDirections.DY];
            ray = null;
            return this;
        }

        /** {@return the same ray for dyn4j} */
        Ray ray() {
            if (ray == null) {
                ray = new Ray(new Vector2(sx, sy), radians);
            }
            return ray;
        }
    }

    /** Every object of the world, in the world's order, the ray meets within range (no broad phase). */
    private List<RayHit> castAll(SimObject self, Vec2 origin, double bearingDeg, double maxRange) {
        Beam beam = new Beam(origin, bearingDeg, directions);
        var hits = new NearestFirst();
        int index = 0;
        for (SimObject o : objects.values()) {
            if (o != self && o.carriedBy == null) {
                RayHit hit = cast(o, beam, maxRange);
                if (hit != null) {
                    hits.add(hit, index);
                }
            }
            index++;
        }
        return hits.list();
    }

    /**
     * Casts one ray against one object; a hit within range joins {@code hits}. A circle is solved in
     * closed form, to the bit of dyn4j's circle cast. A rectangle keeps dyn4j's GJK answer, worked out
     * without allocations ({@link BoxGjkCast}): near a corner it can be off the exact distance by
     * millimetres (GJK stops within its tolerance; see RayShapesTest), and the world's trajectories
     * depend on it. Only the rays that pass within {@link #GJK_MARGIN} of the rectangle, where GJK
     * can answer a hit, are cast. {@return the hit within range, or null}
     */
    private RayHit cast(SimObject o, Beam beam, double maxRange) {
        if (o.shape instanceof Rectangle r && Double.isNaN(reachFrom(o, r, beam, maxRange))) {
            return null;
        }
        return castShape(o, beam, maxRange);
    }

    /**
     * {@return where the ray enters the rectangle grown by {@link #GJK_MARGIN}, GJK's answer being no
     * nearer (0 when it starts inside), or NaN when GJK cannot answer a hit: the ray passes farther}
     */
    private static double reachFrom(SimObject o, Rectangle r, Beam beam, double maxRange) {
        Transform t = o.body.getTransform();
        return RayShapes.boxReachFrom(beam.sx, beam.sy, beam.dx, beam.dy, t.getTranslationX(), t.getTranslationY(),
                t.getCost(), t.getSint(), r.getWidth() / 2, r.getHeight() / 2, GJK_MARGIN, maxRange + BACKOFF);
    }

    /** {@link #cast} for a ray that reaches the object ({@link #reachFrom}): the shape's cast itself. */
    private RayHit castShape(SimObject o, Beam beam, double maxRange) {
        double length = maxRange + BACKOFF;
        Transform t = o.body.getTransform();
        double d;
        if (o.shape instanceof Circle c) {
            d = RayShapes.circle(beam.sx, beam.sy, beam.dx, beam.dy, t.getTranslationX(), t.getTranslationY(),
                    c.getRadius(), length);
        } else if (o.shape instanceof Rectangle r) {
            double w = r.getWidth(), h = r.getHeight();
            if (world.getRaycastDetector() instanceof Gjk gjk) {
                d = BoxGjkCast.cast(beam.sx, beam.sy, beam.dx, beam.dy, w, h, t.getTranslationX(), t.getTranslationY(),
                        t.getCost(), t.getSint(), length, gjk.getRaycastEpsilon(), gjk.getMaxRaycastIterations());
            } else { // another detector: ask it
                Raycast raycast = new Raycast();
                d = world.getRaycastDetector().raycast(beam.ray(), length, r, t, raycast) ? raycast.getDistance() : Double.NaN;
            }
        } else {
            throw new IllegalStateException("object '" + o.id + "' is neither a circle nor a rectangle");
        }
        if (!Double.isNaN(d)) {
            double best = Math.max(0, d - BACKOFF);
            if (best <= maxRange) {
                return new RayHit(best, o.color, o.height, o.id, o.reflectance);
            }
        }
        return null;
    }

    /**
     * A camera's rays, each with the result {@link #castAll} gives it, with a broad phase shared by
     * the fan: the objects out of every ray's reach are dropped once, and each ray tries only the
     * objects whose bounding circle (grown by {@link #REACH_MARGIN}) it crosses. The filter is
     * conservative, so the rays meet the same objects, and their hits keep the order of
     * {@link #castAll} ({@link NearestFirst}).
     *
     * <p>With {@code opaque} (see {@link RayCaster#castFan(Vec2, double[], double, Predicate)}) a ray
     * tries its objects in the order of a lower bound on their hit's distance (where the ray enters
     * the bounding circle, or a rectangle grown by {@link #GJK_MARGIN}), and stops at the first
     * whose bound lies beyond an opaque hit already found: what it leaves out is farther than that
     * hit, so the hits up to the first opaque one are those of {@link #castAll}.
     */
    private List<List<RayHit>> castFan(SimObject self, Vec2 origin, double[] bearingsDeg, double maxRange,
                                       Predicate<RayHit> opaque) {
        int n = bearingsDeg.length;
        double ox = origin.x(), oz = origin.z();
        double length = maxRange + BACKOFF;
        FanScratch f = scratch.sized(objects.size());
        List<SimObject> near = f.near;
        near.clear();
        double[] cx = f.cx, cz = f.cz, reach = f.reach;
        for (SimObject o : objects.values()) {
            if (o == self || o.carriedBy != null) {
                continue;
            }
            Transform t = o.body.getTransform();
            double x = t.getTranslationX(), z = t.getTranslationY(), r = o.boundingRadius + REACH_MARGIN;
            double ex = x - ox, ez = z - oz;
            if (Math.sqrt(ex * ex + ez * ez) > length + r) {
                continue; // every ray's start lies within BACKOFF of the origin, its end within maxRange
            }
            if (o.shape instanceof Rectangle box && RayShapes.boxDistance(ox, oz, x, z, t.getCost(), t.getSint(),
                    box.getWidth() / 2, box.getHeight() / 2) > length + BACKOFF + REACH_MARGIN) {
                continue; // a far wall, whose bounding circle reaches every ray: no ray comes within GJK's margin
            }
            cx[near.size()] = x;
            cz[near.size()] = z;
            reach[near.size()] = r;
            near.add(o);
        }
        int[][] candidates = n >= SECTOR_FAN ? sectors(ox, oz, bearingsDeg, cx, cz, reach, near, f) : null;
        int[] order = f.order;
        double[] bound = f.bound;
        Beam beam = f.beam;
        List<List<RayHit>> fan = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            beam.aim(origin, bearingsDeg[k], directions);
            int[] mine = candidates == null ? null : candidates[k];
            int count = mine == null ? near.size() : mine[0], tries = 0;
            for (int j = 0; j < count; j++) {
                int i = mine == null ? j : mine[j + 1];
                double ex = cx[i] - beam.sx, ez = cz[i] - beam.sy;
                double along = ex * beam.dx + ez * beam.dy, across = ex * beam.dy - ez * beam.dx;
                if (Math.abs(across) <= reach[i] && along >= -reach[i] && along <= length + reach[i]) {
                    SimObject o = near.get(i);
                    double from = o.shape instanceof Rectangle r ? reachFrom(o, r, beam, maxRange) : along - reach[i];
                    if (!Double.isNaN(from)) { // NaN: a rectangle GJK cannot answer a hit for
                        tries = insert(order, bound, tries, i, opaque == null ? 0 : from);
                    }
                }
            }
            var hits = new NearestFirst();
            double stop = Double.POSITIVE_INFINITY; // the nearest opaque hit's distance
            for (int j = 0; j < tries && !(bound[j] - BACKOFF > stop); j++) {
                RayHit hit = castShape(near.get(order[j]), beam, maxRange);
                if (hit != null) {
                    hits.add(hit, order[j]);
                    if (opaque != null && hit.distance() < stop && opaque.test(hit)) {
                        stop = hit.distance();
                    }
                }
            }
            fan.add(hits.list());
        }
        return fan;
    }

    private final FanScratch scratch = new FanScratch();

    /**
     * The arrays a fan works in, kept from one fan to the next where each fan made its own (a
     * camera's frame and each distance sensor's reading made five arrays the size of the world's
     * objects, a beam per ray and a list per ray for the sectors: a quarter of an agent run's allocation). A fan fills what it reads before reading it: the
     * objects' centres and reaches up to {@code near}'s size, the tries up to their count, a ray's
     * sector list up to its count. The world is stepped by one thread, and a fan calls nothing that
     * casts another.
     */
    private static final class FanScratch {
        final List<SimObject> near = new ArrayList<>();
        final Beam beam = new Beam();
        double[] cx = new double[0], cz = cx, reach = cx, bound = cx;
        int[] order = new int[0];
        /** {@link #sectors}' lists by ray, each {@code {count, index...}}, and its rays' bearings. */
        int[][] lists = new int[0][];
        double[] offset = cx;
        final double[] side = new double[2];

        /** {@return this scratch, its per-object arrays holding at least {@code objects}} */
        FanScratch sized(int objects) {
            if (cx.length < objects) {
                cx = new double[objects];
                cz = new double[objects];
                reach = new double[objects];
                bound = new double[objects];
                order = new int[objects];
            }
            return this;
        }

        /** {@return the sectors' lists for {@code rays} rays, each emptied} */
        int[][] lists(int rays) {
            if (lists.length < rays) {
                lists = Arrays.copyOf(lists, rays);
                offset = new double[rays];
            }
            for (int k = 0; k < rays; k++) {
                if (lists[k] == null) {
                    lists[k] = new int[9];
                }
                lists[k][0] = 0;
            }
            return lists;
        }
    }

    /**
     * Puts object i with its bound among the first {@code size} tries, in ascending bound (after
     * those with the same bound: equal bounds keep the order they come in). {@return the new size}
     */
    private static int insert(int[] order, double[] bound, int size, int i, double b) {
        int at = size;
        while (at > 0 && bound[at - 1] > b) {
            order[at] = order[at - 1];
            bound[at] = bound[at - 1];
            at--;
        }
        order[at] = i;
        bound[at] = b;
        return size + 1;
    }

    /** From this many rays on, a fan sorts its objects into the rays' sectors first ({@link #sectors}). */
    static final int SECTOR_FAN = 8;

    /** Slack on the sectors' angles, in radians: far above their rounding; a wider sector only costs a test. */
    private static final double SECTOR_SLACK = 1e-6;

    /**
     * For each ray of a fan, the objects whose bounding circle the ray can cross, as
     * {@code {count, index...}} in the objects' order (the scratch's lists, good until the next fan); null when the rays' bearings do not grow
     * from the first (then every ray tries every object). Every ray starts on the line through the
     * origin along its bearing, so it meets the grown circle of radius r around a centre at distance
     * D only when its bearing is within {@code asin(r / D)} of the centre's (so within its tangent,
     * {@code r / sqrt(D² - r²)}, which costs less); a centre nearer than
     * {@code sqrt(r² + (r + BACKOFF)²)} may be met behind the origin, and goes to every ray. A
     * rectangle whose circle's sector is that wide (the arena's walls, mostly) gets the sector of its
     * corners instead ({@link #cornerSector}). The test in {@link #castFan} then runs on these
     * candidates as before, so the casts are the same.
     */
    private static int[][] sectors(double ox, double oz, double[] bearingsDeg, double[] cx, double[] cz, double[] reach,
                                   List<SimObject> near, FanScratch scratch) {
        int n = bearingsDeg.length, objects = near.size();
        double first = Math.toRadians(bearingsDeg[0]);
        int[][] out = scratch.lists(n);
        double[] offset = scratch.offset; // each ray's bearing after the first's, radians (the first n)
        for (int k = 0; k < n; k++) {
            offset[k] = Math.toRadians(bearingsDeg[k]) - first;
            if (k > 0 && !(offset[k] >= offset[k - 1]) || offset[k] > Math.PI / 2) {
                return null;
            }
        }
        double[] side = scratch.side; // the sector's edges after the centre's bearing, radians (with the slack)
        for (int i = 0; i < objects; i++) {
            double ex = cx[i] - ox, ez = cz[i] - oz, r = reach[i];
            double d = Math.sqrt(ex * ex + ez * ez);
            boolean bounded = d * (1 - SECTOR_SLACK) > Math.sqrt(r * r + (r + BACKOFF) * (r + BACKOFF)) + SECTOR_SLACK;
            if (bounded) {
                double sine = r / d; // below 0.71 here, so tan(asin(sine)), no less than asin(sine), is a cheaper bound
                double half = sine / Math.sqrt(1 - sine * sine) + SECTOR_SLACK;
                side[0] = -half;
                side[1] = half;
            }
            if ((!bounded || side[1] > WIDE_SECTOR) && near.get(i).shape instanceof Rectangle box) {
                bounded = cornerSector(ox, oz, ex, ez, near.get(i).body.getTransform(), box, side) || bounded;
            }
            int from = 0, to = n - 1;
            if (bounded) {
                double at = Math.atan2(ez, ex) - first; // the centre's bearing after the first ray's, in (-3π, 3π)
                at -= 2 * Math.PI * Math.floor((at + Math.PI) / (2 * Math.PI)); // into [-π, π)
                if (at + side[1] < offset[0] - SECTOR_SLACK || at + side[0] > offset[n - 1] + SECTOR_SLACK) {
                    if (at + 2 * Math.PI + side[0] > offset[n - 1] + SECTOR_SLACK
                            && at - 2 * Math.PI + side[1] < offset[0] - SECTOR_SLACK) {
                        continue; // no ray's bearing comes within the sector, nor a turn later or earlier
                    }
                    at += at < 0 ? 2 * Math.PI : -2 * Math.PI;
                }
                from = firstAtLeast(offset, n, at + side[0]);
                to = firstAtLeast(offset, n, Math.nextUp(at + side[1])) - 1;
            }
            for (int k = from; k <= to; k++) {
                int[] list = out[k];
                if (list[0] + 1 == list.length) {
                    list = out[k] = Arrays.copyOf(list, Math.min(objects + 1, 2 * list.length));
                }
                list[++list[0]] = i;
            }
        }
        return out;
    }

    /**
     * From this half-width of a circle's sector on (radians), a rectangle's corners are worth their
     * four arc tangents: a wall beside or behind the camera then reaches none of its rays, where its
     * bounding circle (half the wall's length) reached them all.
     */
    static final double WIDE_SECTOR = 0.5;

    /**
     * The sector of a rectangle grown by {@link #GJK_MARGIN} (what {@link #reachFrom} tests), seen
     * from an origin farther than {@link #BACKOFF} from it: a ray starting within {@code BACKOFF}
     * behind the origin then meets it only ahead of the origin, along a bearing between its corners'
     * (a convex shape the origin is outside of; its centre's bearing lies between them, so each
     * corner's is within half a turn of it). Puts the edges, after the centre's bearing
     * {@code (ex, ez)}, into {@code side}. {@return false, side untouched, when the origin is too near}
     */
    private static boolean cornerSector(double ox, double oz, double ex, double ez, Transform t, Rectangle box, double[] side) {
        double hx = box.getWidth() / 2 + GJK_MARGIN, hy = box.getHeight() / 2 + GJK_MARGIN;
        double cos = t.getCost(), sin = t.getSint();
        if (!(RayShapes.boxDistance(ox, oz, t.getTranslationX(), t.getTranslationY(), cos, sin, hx, hy) > BACKOFF + SECTOR_SLACK)) {
            return false;
        }
        double low = Double.POSITIVE_INFINITY, high = Double.NEGATIVE_INFINITY;
        for (int corner = 0; corner < 4; corner++) {
            double u = (corner & 1) == 0 ? hx : -hx, v = (corner & 2) == 0 ? hy : -hy;
            double qx = ex + cos * u - sin * v, qz = ez + sin * u + cos * v; // the corner, from the origin
            double angle = Math.atan2(ex * qz - ez * qx, ex * qx + ez * qz); // after the centre's bearing
            low = Math.min(low, angle);
            high = Math.max(high, angle);
        }
        side[0] = low - SECTOR_SLACK;
        side[1] = high + SECTOR_SLACK;
        return true;
    }

    /** {@return the first index below {@code length} whose value is at least {@code x}, or the length} */
    private static int firstAtLeast(double[] sorted, int length, double x) {
        int lo = 0, hi = length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (sorted[mid] < x) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }
}
