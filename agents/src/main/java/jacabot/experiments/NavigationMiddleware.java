package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.util.EnumMap;
import java.util.Map;

/**
 * Experiment 3's middleware (thesis Chapter 4 §3.2): {@code location(X,Y,Z)} from the GPS
 * (truncated to centimetres, as the thesis does), {@code orientation(O)} from the compass (degrees
 * from north, clockwise: the thesis' {@code convertBearing}), both from the start (the superclass
 * publishes them, {@code startLocating}), and {@code computeAngle}; signals {@code targetReached} when the
 * robot is within the threshold of the target point, {@code noAccess} when it comes near the
 * storage area and {@code outOfStorageArea} when it has left it after {@code waitExit}.
 *
 * <p>Tuning (ours): {@code targetReached} is edge-triggered and re-armed when the robot is
 * farther than twice the threshold from the target; before, it was re-armed only by
 * {@code setUpTargetPoint}, so the second cylinder was carried through the storage point without
 * a signal.
 */
public class NavigationMiddleware extends ObjectPickingMiddleware {
    private double[] target;
    private double[] storage;
    private double threshold = 0.04;
    private boolean targetSignalled;
    private boolean inArea;
    private boolean waitingExit;
    /** The map of obstacles met and the route to a target point (not in the thesis), once the agent asked for it. */
    private RouteMap routes;
    /** The way the robot has come (not in the thesis), once the agent asked for it. */
    private Trail trail;

    @Override
    protected void defineProperties() {
        super.defineProperties();
        startLocating();
    }

    /** The point to reach; the first one set is the storage point. */
    @OPERATION
    void setUpTargetPoint(double x, double y, double z) {
        target = new double[] {x, y, z};
        if (storage == null) {
            storage = target.clone();
        }
        targetSignalled = false;
    }

    @OPERATION
    void setThreshold(double t) {
        threshold = t;
    }

    /** Watch for the robot leaving the storage area ({@code outOfStorageArea}). */
    @OPERATION
    void waitExit() {
        waitingExit = true;
    }

    /**
     * Starts the map of obstacles the robot meets (not in the thesis) for an arena of {@code width} by
     * {@code depth} metres; an obstacle stays on it {@code memoryMs} after it was last seen.
     */
    @OPERATION
    void routeMap(double width, double depth, double memoryMs) {
        if (!(width > RouteMap.CELL) || !(depth > RouteMap.CELL) || !(memoryMs > 0)) {
            failed("routeMap(Width, Depth, MemoryMs) needs an arena over " + RouteMap.CELL + " m a side and a memory > 0, got "
                    + width + ", " + depth + ", " + memoryMs);
            return;
        }
        routes = new RouteMap(width, depth, KHEPERA_RADIUS + ROUTE_MARGIN, (long) memoryMs);
    }

    /**
     * Guess that a wall's face seen goes on for {@code metres} past its seen end where the robot has not
     * driven (not in the thesis: {@link RouteMap#guessWalls}); fails before {@code routeMap}.
     */
    @OPERATION
    void routeWallGuess(double metres) {
        if (guessable("routeWallGuess", metres)) {
            routes.guessWalls(metres);
        }
    }

    /**
     * Makes the wall guess firm for its first {@code metres} past a face's seen end (not in the thesis:
     * {@link RouteMap#guessWallsFirm}; the side sensors' open rays end a guess); fails before {@code routeMap}.
     */
    @OPERATION
    void routeWallFirm(double metres) {
        if (guessable("routeWallFirm", metres)) {
            routes.guessWallsFirm(metres);
        }
    }

    /** Whether a wall guess of {@code metres} can be set; the operation fails with one line otherwise. */
    private boolean guessable(String operation, double metres) {
        if (routes == null || !(metres >= 0)) {
            failed(operation + "(Metres) needs routeMap first and Metres >= 0, got " + metres);
            return false;
        }
        return true;
    }

    /**
     * The point to head for on the way to (tx, tz) (not in the thesis): the target itself when the straight
     * way is free of obstacles met, or no way round them is known; else the farthest point of the route
     * round them that the robot can reach in a straight line. Observable: {@code route(Wx, Wz, Cells)}
     * (Cells: the route's length in cells, 0 for the straight way). Without {@code routeMap}: the target.
     */
    @OPERATION
    void routeTo(double tx, double tz, OpFeedbackParam<Double> wx, OpFeedbackParam<Double> wz) {
        double[] here = position();
        double[] w = routes == null || here == null ? new double[] {tx, tz} : routes.waypoint(here[0], here[1], tx, tz, simTimeMs());
        double x = Math.round(w[0] * 1000) / 1000.0, z = Math.round(w[1] * 1000) / 1000.0;
        wx.set(x);
        wz.set(z);
        int cells = routes == null ? 0 : routes.lastRoute().size();
        if (hasObsProperty("route")) {
            getObsProperty("route").updateValues(x, z, cells);
        } else {
            defineObsProperty("route", x, z, cells);
        }
    }

    /**
     * The length, metres, of the way from (x, z) to (tx, tz) round the obstacles met (not in the thesis:
     * {@link RouteMap#routeLength}); without {@code routeMap}, the straight distance.
     */
    @OPERATION
    void routeLength(double x, double z, double tx, double tz, OpFeedbackParam<Double> length) {
        double l = routes == null ? Math.hypot(tx - x, tz - z) : routes.routeLength(x, z, tx, tz, simTimeMs());
        length.set(Math.round(l * 1000) / 1000.0);
    }

    /** Keeps the way the robot drives from now on (not in the thesis): {@code trailTo} goes back along it. */
    @OPERATION
    void keepTrail() {
        if (trail == null) {
            trail = new Trail();
        }
    }

    /**
     * The point to head for on the way to (tx, tz) along the way the robot has come (not in the thesis):
     * when its trail passed near both the robot and the target, a point a little ahead on the shortest way
     * through the trail; else (or without {@code keepTrail}) the target itself.
     */
    @OPERATION
    void trailTo(double tx, double tz, OpFeedbackParam<Double> wx, OpFeedbackParam<Double> wz) {
        double[] here = position();
        double[] w = trail == null || here == null ? null : trail.waypoint(here[0], here[1], tx, tz);
        boolean target = w == null || (w[0] == tx && w[1] == tz);
        wx.set(target ? tx : Math.round(w[0] * 1000) / 1000.0);
        wz.set(target ? tz : Math.round(w[1] * 1000) / 1000.0);
    }

    /** The Khepera's body radius and its distance sensors' bearings (degrees, positive to the right). */
    static final double KHEPERA_RADIUS = 0.0285;
    private static final Map<SensorKind, Double> SENSOR_BEARING = new EnumMap<>(Map.of(
            SensorKind.LEFT_DISTANCE, -90.0, SensorKind.FRONT_LEFT_DISTANCE, -45.0, SensorKind.CENTRAL_DISTANCE, 0.0,
            SensorKind.FRONT_RIGHT_DISTANCE, 45.0, SensorKind.RIGHT_DISTANCE, 90.0));
    /** How far from the body a route keeps, metres, beyond the body's radius. */
    static final double ROUTE_MARGIN = 0.01;
    /** With a firm wall guess: a side sensor (±90 degrees) reading under {@link #MAP_LEVEL} saw the floor open this far from the body, metres. */
    static final double OPEN_REACH = 0.04;
    /** A reading over this is an obstacle put on the map (about 5 cm from the body). */
    static final double MAP_LEVEL = 100;
    /** The Khepera's infra-red calibration, reading to metres from the body: {reading, distance} pairs, readings falling. */
    private static final double[][] CALIBRATION = {{1000, 0}, {480, 0.015}, {350, 0.025}, {200, 0.04}, {0, 0.06}};
    /** The held cylinder's centre, metres ahead of the robot's, and the radius round it where no obstacle is mapped. */
    private static final double HOLD_AHEAD = 0.05, HOLD_RADIUS = 0.03;

    /** {@return the distance from the body, metres, of an obstacle giving the reading {@code value}} */
    static double rangeOf(double value) {
        for (int k = 1; k < CALIBRATION.length; k++) {
            double[] hi = CALIBRATION[k - 1], lo = CALIBRATION[k];
            if (value >= lo[0]) {
                double f = (hi[0] - Math.min(value, hi[0])) / (hi[0] - lo[0]);
                return hi[1] + f * (lo[1] - hi[1]);
            }
        }
        return CALIBRATION[CALIBRATION.length - 1][1];
    }

    /** Puts what a distance sensor sees on the route map: the point of the obstacle's surface. */
    private void mapReading(SensorKind kind, double value) {
        if (routes == null) {
            return; // no map asked for: nothing more per reading
        }
        Double bearing = SENSOR_BEARING.get(kind);
        double[] here = position();
        double compass = heading();
        if (bearing == null || here == null || Double.isNaN(compass)) {
            return;
        }
        if (!(value > MAP_LEVEL)) {
            if (routes.firmGuess() && Math.abs(bearing) == 90) {
                double a = Math.toRadians(compass + bearing), d0 = KHEPERA_RADIUS, d1 = KHEPERA_RADIUS + OPEN_REACH;
                routes.seenFree(here[0] + d0 * Math.cos(a), here[1] + d0 * Math.sin(a), here[0] + d1 * Math.cos(a), here[1] + d1 * Math.sin(a));
            }
            return;
        }
        double a = Math.toRadians(compass + bearing), d = KHEPERA_RADIUS + rangeOf(value);
        double px = here[0] + d * Math.cos(a), pz = here[1] + d * Math.sin(a);
        if (getObsProperty("caught").booleanValue()) {
            double h = Math.toRadians(compass);
            if (Math.hypot(px - here[0] - HOLD_AHEAD * Math.cos(h), pz - here[1] - HOLD_AHEAD * Math.sin(h)) < HOLD_RADIUS) {
                return; // the cylinder in the gripper
            }
        }
        routes.obstacle(px, pz, simTimeMs());
    }

    @Override
    protected void onReading(SensorInfo info, SensorKind kind) {
        switch (kind) {
            case GPS:
                double[] c = info.getCoord();
                if (routes != null) {
                    routes.standing(c[0], c[2]);
                }
                if (trail != null) {
                    trail.at(c[0], c[2]);
                }
                super.onReading(info, kind); // the progress watch, location
                checkTarget(c[0], c[2]);
                checkStorage(c[0], c[2]);
                break;
            case COMPASS:
                super.onReading(info, kind); // orientation
                break;
            default:
                mapReading(kind, info.getVal());
                super.onReading(info, kind);
        }
    }

    private void checkTarget(double x, double z) {
        if (target == null) {
            return;
        }
        double dx = Math.abs(x - target[0]);
        double dz = Math.abs(z - target[2]);
        if (!targetSignalled && dx < threshold && dz < threshold) {
            targetSignalled = true;
            log("Target reached");
            signal("targetReached");
        } else if (targetSignalled && (dx > 2 * threshold || dz > 2 * threshold)) {
            targetSignalled = false; // left it: the next arrival counts again
        }
    }

    private void checkStorage(double x, double z) {
        if (storage == null) {
            return;
        }
        boolean near = Math.hypot(x - storage[0], z - storage[2]) < ACCESS_RADIUS;
        if (near && !inArea) {
            signal("noAccess");
        } else if (!near && inArea && waitingExit) {
            waitingExit = false;
            signal("outOfStorageArea");
        }
        inArea = near;
    }
}
