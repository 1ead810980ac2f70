package jacabot.robot.baseline;

import jacabot.sim.device.Camera;
import jacabot.sim.device.Section;
import jacabot.sim.geom.Vec2;
import jacabot.sim.world.AreaSpec;
import java.util.ArrayList;
import java.util.List;

/**
 * The strategies the default agents have and the thesis' C programs lack, written once as the helper
 * routines a careful C programmer keeps beside the main loops of the equal-capability baselines,
 * with the same figures as the agents' skill parameters (skills/far-sight.asl, sweep.asl,
 * recovery.asl, progress-watch.asl): far sight from the whole camera image and homing on what it
 * shows, a sweep of the arena by lanes with looks around (object picking's too, as its agent's),
 * a watch on progress, and escapes from waits that do not end.
 *
 * <p>Every routine here steps the world itself and returns as soon as the main loop has something
 * more important to do: an obstacle ahead, a cylinder in sight, the controller's urgent test.
 */
final class EqualCapabilities {
    /** Far sight: homing speeds (wheel units), "far" from this distance (m), a chase given up after (ms). */
    static final double TRAVEL = 100, APPROACH = 40, FAR = 0.45;
    static final long HOMING_GIVE_UP = 40_000, IGNORE_FOR = 15_000, LOST_SIGHT_IGNORE = 5_000, KEEP_STEERING = 1_500;
    /** Sweep: lanes apart (m), a look around every (ms), a waypoint given up without progress (ms, m). */
    static final double LANES = 0.5, WAYPOINT_PROGRESS = 0.1;
    static final long LOOK_EVERY = 25_000, WAYPOINT_PATIENCE = 20_000, LOOK_TURN = 6_800;
    /** Progress watch: moved less than this (m) in this long (ms) is stuck. */
    static final double STUCK_DISTANCE = 0.05;
    static final long STUCK_WINDOW = 15_000;
    /** ms without a cylinder before the sweep (skills/sweep.asl). */
    static final long SWEEP_AFTER = 45_000;
    /** Recovery: an obstacle may stay this long (s) before the escape; backing off (s). */
    static final double CLEAR_PATIENCE = 3, ESCAPE_BACK = 1.2;
    /** The experiments' cylinders: radius in metres (the sighting's distance from its apparent width). */
    static final double CYLINDER_RADIUS = 0.0125;

    /** A red cylinder in the image: degrees right of the centre, rough distance in metres. */
    record Sighting(double offset, double distance) {
    }

    private final ObjectPickingBaseline c;
    private final AreaSpec storage;
    private final long searchAfter;
    private long lastFound, homingSince = -1, lastSeen, ignoreUntil, lastLook, waypointSince, watchSince;
    private double closest;
    private Vec2 watchFrom;
    private List<Vec2> waypoints;
    private Vec2 waypoint;

    /**
     * @param storage     the storage point (no sweep waypoint and no sighting there), or null (object picking)
     * @param searchAfter ms without a cylinder before the search
     */
    EqualCapabilities(ObjectPickingBaseline controller, AreaSpec storage, long searchAfter) {
        this.c = controller;
        this.storage = storage;
        this.searchAfter = searchAfter;
    }

    /** The main loop's "nothing else to do": home on a sighting, else search, else random motion. */
    void wander() {
        long now = c.now();
        if (watchFrom == null) {
            lastFound = now;
            lastLook = now;
            watch(now);
        }
        if (progressLost()) {
            c.print("No progress: escaping");
            escape();
            return;
        }
        if (homingSince >= 0 && now - homingSince > HOMING_GIVE_UP) {
            c.print("The cylinder in sight cannot be reached: looking elsewhere");
            homingSince = -1;
            ignoreUntil = now + IGNORE_FOR;
            escape();
            return;
        }
        Sighting s = c.mayPick() ? sight() : null;
        if (s != null) {
            if (homingSince < 0) {
                homingSince = now;
            }
            lastSeen = now;
            steer(s);
            return;
        }
        if (homingSince >= 0) {
            if (now - lastSeen < KEEP_STEERING) {
                return;
            }
            homingSince = -1;
            ignoreUntil = now + LOST_SIGHT_IGNORE;
        }
        if (now - lastFound > searchAfter) {
            sweepStep(now);
            return;
        }
        c.motion.poll(now);
    }

    /** A cylinder picked: the search is over. */
    void found() {
        lastFound = c.now();
        homingSince = -1;
        waypoint = null;
    }

    /** Back off, turn a random angle, go on (skills/recovery.asl's escape). */
    void escape() {
        double m = c.maxSpeed;
        c.robot.setSpeeds(-m / 2, -m / 2);
        c.pause(ESCAPE_BACK);
        double turn = 0.7 + c.random.nextDouble() * 1.5;
        int side = c.random.nextBoolean() ? 1 : -1;
        c.robot.setSpeeds(side * m / 2, -side * m / 2);
        c.pause(turn);
        c.robot.setSpeeds(m / 2, m / 2);
        watch(c.now());
    }

    /** {@return whether the robot moved less than {@link #STUCK_DISTANCE} in the last window (then watches anew)} */
    boolean progressLost() {
        long now = c.now();
        Vec2 here = new Vec2(c.io.x(), c.io.z());
        if (watchFrom == null || now - watchSince > 2 * STUCK_WINDOW) {
            watch(now); // not watched for a while (charging, picking): start again
            return false;
        }
        if (now - watchSince < STUCK_WINDOW) {
            return false;
        }
        boolean stuck = here.distanceTo(watchFrom) < STUCK_DISTANCE;
        watch(now);
        return stuck;
    }

    private void watch(long now) {
        watchSince = now;
        watchFrom = new Vec2(c.io.x(), c.io.z());
    }

    /**
     * {@return the widest run of image columns holding a red pixel (the thesis' red test), as an
     * offset and a distance, or null}; not while ignoring sightings, nor one that lies in the storage
     * area (a delivered cylinder)
     */
    Sighting sight() {
        Camera cam = c.io.camera;
        int[] image = cam.getImage();
        if (image == null || c.now() < ignoreUntil) {
            return null;
        }
        int w = cam.getWidth(), h = cam.getHeight();
        int bestFrom = -1, best = 0, from = -1;
        for (int x = 0; x <= w; x++) {
            boolean red = x < w && redColumn(image, w, h, x);
            if (red && from < 0) {
                from = x;
            } else if (!red && from >= 0) {
                if (x - from > best) {
                    best = x - from;
                    bestFrom = from;
                }
                from = -1;
            }
        }
        if (best == 0) {
            return null;
        }
        double perColumn = cam.getFov() / w;
        double offset = (bestFrom + best / 2.0 - w / 2.0) * perColumn;
        double distance = CYLINDER_RADIUS / Math.tan(Math.toRadians(best * perColumn / 2));
        if (storage != null) {
            Vec2 seen = new Vec2(c.io.x(), c.io.z()).plus(Vec2.ofBearing(c.io.bearing() + offset).times(distance));
            if (seen.distanceTo(storage.centre()) < storage.radius() + 0.1) {
                return null;
            }
        }
        return new Sighting(offset, distance);
    }

    private static boolean redColumn(int[] image, int w, int h, int x) {
        for (int y = 0; y < h; y++) {
            int r = Camera.imageGetRed(image, w, x, y), g = Camera.imageGetGreen(image, w, x, y), b = Camera.imageGetBlue(image, w, x, y);
            if (r > 40 && r > KheperaIo.RED_RATIO * g && r > KheperaIo.RED_RATIO * b) {
                return true;
            }
        }
        return false;
    }

    /** Turn on the spot towards a cylinder well aside, else steer towards it (fast while far). */
    private void steer(Sighting s) {
        double m = c.maxSpeed, off = s.offset();
        if (off > 12) {
            c.robot.setSpeeds(m / 4, -m / 4);
        } else if (off < -12) {
            c.robot.setSpeeds(-m / 4, m / 4);
        } else if (s.distance() >= FAR) {
            c.robot.setSpeeds(Math.min(m, TRAVEL - 10 + off), Math.min(m, TRAVEL - 10 - off));
        } else {
            c.robot.setSpeeds(APPROACH + off, APPROACH - off);
        }
    }

    /** One step of the sweep: reached, look around, skipped, or turn towards the waypoint and drive 2 s. */
    private void sweepStep(long now) {
        if (waypoints == null) {
            waypoints = lanes();
        }
        if (waypoint == null) {
            nextWaypoint(now);
        }
        if (waypoint == null) {
            c.motion.poll(now);
            return;
        }
        double d = c.io.distanceTo(waypoint.x(), waypoint.z());
        if (d < 0.1) {
            nextWaypoint(now);
            lookAround();
        } else if (now - lastLook > LOOK_EVERY) {
            lookAround();
        } else if (now - waypointSince > WAYPOINT_PATIENCE) {
            nextWaypoint(now);
        } else {
            if (d < closest - WAYPOINT_PROGRESS) {
                closest = d;
                waypointSince = now;
            }
            if (turnTowards(c.io.bearingTo(waypoint.x(), waypoint.z()))) {
                drive(TRAVEL, 2);
            }
        }
    }

    /** The sweep's waypoints: lanes {@link #LANES} apart, ends alternating, none in the storage area (if any). */
    private List<Vec2> lanes() {
        var arena = c.world.spec().arena();
        double hx = arena.width() / 2 - LANES / 2, hz = arena.depth() / 2 - LANES / 2;
        int n = (int) Math.floor(2 * hz / LANES);
        List<Vec2> out = new ArrayList<>();
        for (int i = 0; i <= n; i++) {
            double z = -hz + i * LANES;
            for (double x : i % 2 == 0 ? new double[] {-hx, hx} : new double[] {hx, -hx}) {
                if (storage == null || new Vec2(x, z).distanceTo(storage.centre()) > NavigationBaseline.NO_ACCESS + 0.1) {
                    out.add(new Vec2(x, z));
                }
            }
        }
        return out;
    }

    private void nextWaypoint(long now) {
        if (waypoints.isEmpty()) {
            waypoint = null;
            return;
        }
        waypoint = waypoints.remove(0);
        waypoints.add(waypoint);
        waypointSince = now;
        closest = Double.POSITIVE_INFINITY;
    }

    /** A full turn on the spot, slowly enough for the camera; ends at a sighting or an obstacle. */
    void lookAround() {
        lastLook = c.now();
        double m = c.maxSpeed;
        c.robot.setSpeeds(-m / 2, m / 2);
        long end = c.now() + LOOK_TURN;
        while (c.now() < end && !interrupted()) {
            c.step();
        }
        c.robot.setSpeeds(0, 0);
    }

    /** Spins towards a bearing, for 4 s at most; {@return whether it faces it (false when interrupted)} */
    private boolean turnTowards(double bearing) {
        double m = c.maxSpeed;
        long end = c.now() + 4_000;
        while (c.now() < end) {
            double gap = KheperaIo.gap(bearing, c.io.bearing());
            if (Math.abs(gap) < 5) {
                return true;
            }
            double speed = Math.abs(gap) > 30 ? m / 2 : m / 8;
            c.robot.setSpeeds(gap > 0 ? speed : -speed, gap > 0 ? -speed : speed);
            c.step();
            if (interrupted()) {
                return false;
            }
        }
        return true;
    }

    /** Straight on at {@code speed} for {@code seconds}, or until interrupted. */
    private void drive(double speed, double seconds) {
        c.robot.setSpeeds(speed, speed);
        long end = c.now() + Math.round(seconds * 1000);
        while (c.now() < end && !interrupted()) {
            c.step();
        }
    }

    /** {@return whether the main loop has something more important: an obstacle, a sighting, a red section, an urgent task, the storage area} */
    private boolean interrupted() {
        return c.obstacleAhead() || c.urgent() || sight() != null || c.io.isRed(Section.CENTRE) || nearStorage();
    }

    /** {@return whether the robot, empty, is about to enter the storage area (the main loop turns it away)} */
    private boolean nearStorage() {
        return storage != null && !c.picked && c.io.distanceTo(storage.x(), storage.z()) < NavigationBaseline.NO_ACCESS + 0.03
                && Math.abs(KheperaIo.gap(c.io.bearingTo(storage.x(), storage.z()), c.io.bearing())) < 90;
    }
}
