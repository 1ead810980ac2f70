package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.robot.link.Command;
import jacabot.robot.link.CommandCode;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * Experiment 2's middleware (thesis Chapter 4 §2.2), for the Khepera: on top of obstacle
 * detection, {@code centralSensor}, {@code caught}, {@code picked}; signals {@code cylinderDetected}
 * (the central sensor very close and red at least twice green and blue on the camera's centre
 * section), {@code cylinderLeft}/{@code cylinderRight} (red on that side of the camera image, not
 * in its centre), {@code cylinderBeyond} (the lateral cylinder, turned towards, is now ahead: red
 * in the centre section), {@code fallen} (the
 * carried cylinder left the gripper) and {@code lateralObstacle("left"|"right")}; and (not in the thesis) the
 * derived percept {@code stuck}, from the GPS: no progress though the robot is meant to move. Once the
 * agent asks ({@code publishLocation}, not in the thesis' experiment 2), the GPS and compass as
 * experiment 3's percepts too: {@code location(X,Y,Z)}, {@code orientation(O)} (see {@link NavigationMiddleware}).
 */
public class ObjectPickingMiddleware extends ObstacleAvoidanceMiddleware {
    // Tuning (ours). The thesis (§2.1) checks the camera's lateral sections when a lateral
    // distance sensor sees something. On this Khepera no distance sensor and camera section look
    // the same way: the camera's 60° field ends at ±30°, the front-left/right sensors look at
    // ±45° (measured: a cylinder at 45° reads 860 and is out of the picture; at 20° it is red in
    // the side section and no sensor sees it). So a red side section, within the camera's red
    // range (about 10 cm), is the lateral cylinder; and cylinderBeyond means the cylinder, turned
    // towards, is now in the centre section, beyond the front, to be approached.
    static final double VERY_CLOSE = 480;
    static final double RED_RATIO = 2;
    static final double HOLD_FORCE = -10;
    private int[] rgb = new int[9];
    private boolean cylinderSignalled;
    private String lateralCylinder;
    /**
     * A lateral cylinder not turned to within this time is forgotten (not in the thesis): the agent may not
     * act on the signal (busy, or near the storage area), and until then neither lateral cylinders
     * nor far ones were signalled again: the robot drove past cylinders for the rest of the run.
     */
    static final long LATERAL_MEMORY_MS = 6000;
    private long lateralSinceMs;
    private boolean holding;
    private double armPosition = 0;
    /** Sides whose very-close lateral obstacle was signalled; re-armed when that side is safe. */
    private final Set<String> lateralSignalled = new HashSet<>();

    // Progress (not in the thesis, a derived percept): "stuck" is signalled when the GPS position stayed
    // within a radius for a time (pressed against something, dithering in front of a box, or
    // circling round an obstacle); the agent sets both windows (progressWindows) and decides
    // (it ignores the signal while it stays on purpose: picking, at the charger).
    private long[] windowMs = {6000, 30000};
    private double[] windowRadius = {0.04, 0.12};
    private final double[][] anchor = new double[2][];
    // Far sight (not in the thesis): with scanForCylinders the whole camera image comes too, and a red run
    // in it is signalled as cylinderSighted(Offset, Distance) every sightingEvery ms at most,
    // unless it points into an area the agent excluded (a delivered cylinder in the storage area).
    private boolean scanning;
    private long sightingEvery = 400;
    private long lastSightingMs = Long.MIN_VALUE / 2;
    private double fov = 60;
    private final List<double[]> excluded = new ArrayList<>();
    // every red run is a sighting, not only the widest (sightEveryRedRun): the first not excluded
    private boolean everyRun;
    /** The last GPS position (x, z) and compass heading (the thesis' orientation, degrees), when known. */
    private double[] position;
    private double heading = Double.NaN;
    /** Whether {@code location} and {@code orientation} are observable properties. */
    private boolean locating;

    /** How close to the storage point the robot may come without a cylinder (metres). */
    static final double ACCESS_RADIUS = 0.15;
    /** Sets the progress windows: stuck if within {@code r1} metres for {@code t1} ms, or within {@code r2} for {@code t2}. */
    @OPERATION
    void progressWindows(double t1, double r1, double t2, double r2) {
        windowMs = new long[] {(long) t1, (long) t2};
        windowRadius = new double[] {r1, r2};
    }

    /**
     * Sends the whole camera image too and signals far cylinders (not in the thesis), at most one signal per
     * {@code everyMs}; {@code fovDegrees} is the camera's field of view.
     */
    @OPERATION
    void scanForCylinders(double everyMs, double fovDegrees) {
        scanning = true;
        sightingEvery = Math.max(40, (long) everyMs);
        fov = fovDegrees;
        send(Command.enableSensor(SensorKind.CAMERA_IMAGE, 40));
    }

    /**
     * Looks at every red run of the image, widest first, and signals the first one outside the
     * excluded areas (not in the thesis): with the widest alone, the pile in the storage area hid a
     * lone cylinder in the same image.
     */
    @OPERATION
    void sightEveryRedRun() {
        everyRun = true;
    }

    /** Cylinders seen inside this circle are not signalled (e.g. those already delivered). */
    @OPERATION
    void ignoreCylindersNear(double x, double z, double radius) {
        excluded.add(new double[] {x, z, radius});
    }

    /**
     * Publishes the GPS and the compass as {@code location(X,Y,Z)} (truncated to centimetres, as the
     * thesis does) and {@code orientation(O)} (degrees from north, clockwise: the thesis'
     * {@code convertBearing}), experiment 3's percepts (not in the thesis' experiment 2: the
     * object-picking agent's sweep search heads for its waypoints with them).
     */
    @OPERATION
    void publishLocation() {
        startLocating();
    }

    /** Defines {@code location} and {@code orientation}, updated from now on with each GPS and compass reading. */
    protected void startLocating() {
        if (!locating) {
            locating = true;
            defineObsProperty("location", 0.0, 0.0, 0.0);
            defineObsProperty("orientation", 0.0);
        }
    }

    /** The heading (degrees from north, clockwise) from (x, z) to (tx, tz). */
    @OPERATION
    void computeAngle(double x, double z, double tx, double tz, OpFeedbackParam<Double> desired) {
        desired.set(bearing(x, z, tx, tz));
    }

    static double bearing(double x, double z, double tx, double tz) {
        double deg = Math.toDegrees(Math.atan2(tz - z, tx - x));
        deg = deg < 0 ? deg + 360 : deg;
        return Math.round(deg * 100) / 100.0;
    }

    private static double trunc(double v) {
        return Math.floor(v * 100) / 100.0;
    }

    /** The compass heading as the thesis' orientation: degrees, from north-vector {@code n}. */
    static double orientation(double[] n) {
        double bearing = Math.toDegrees(Math.atan2(n[0], n[2])) - 90;
        return bearing < 0 ? bearing + 360 : bearing;
    }

    protected void noteCompass(double[] n) {
        heading = orientation(n);
    }

    /** {@return the last GPS position (x, z), or null before the first} */
    protected double[] position() {
        return position;
    }

    /** {@return the last compass heading as the thesis' orientation (degrees), NaN before the first} */
    protected double heading() {
        return heading;
    }

    private void sight(SensorInfo camera) {
        if (!scanning || holding || stopDistance || cylinderSignalled || lateralCylinder != null
                || simTimeMs() - lastSightingMs < sightingEvery) {
            return; // before the image is scanned: most readings end here
        }
        Optional<CylinderSighting> sighting = everyRun
                ? camera.readInts(image -> CylinderSighting.all(image, fov)).stream().filter(s -> !excluded(s)).findFirst()
                : camera.readInts(image -> CylinderSighting.find(image, fov)).filter(s -> !excluded(s)); // read only
        sighting.ifPresent(s -> {
            lastSightingMs = simTimeMs();
            signal("cylinderSighted", Math.round(s.offset() * 10) / 10.0, Math.round(s.distance() * 100) / 100.0);
        });
    }

    private void forgetStaleLateral() {
        if (lateralCylinder != null && simTimeMs() - lateralSinceMs > LATERAL_MEMORY_MS) {
            lateralCylinder = null;
        }
    }

    /** Whether the sighting's ray meets an excluded area about as far as the cylinder seems to be. */
    private boolean excluded(CylinderSighting s) {
        if (position == null || Double.isNaN(heading)) {
            return false;
        }
        double a = Math.toRadians(heading + s.offset());
        double ux = Math.cos(a), uz = Math.sin(a);
        for (double[] e : excluded) {
            double dx = e[0] - position[0], dz = e[1] - position[1];
            double along = dx * ux + dz * uz;
            double across = Math.abs(dx * uz - dz * ux);
            if (Math.hypot(dx, dz) < e[2] || (across < e[2] && along > 0.5 * s.distance() - 0.1 && along < 2 * s.distance() + 0.1)) {
                return true;
            }
        }
        return false;
    }

    protected void checkProgress(double x, double z) {
        position = new double[] {x, z};
        long now = simTimeMs();
        for (int k = 0; k < 2; k++) {
            double[] a = anchor[k];
            // a stop does not restart the window: stopping and turning back to the same place is no progress
            if (a == null || Math.hypot(x - a[0], z - a[1]) > windowRadius[k]) {
                anchor[k] = new double[] {x, z, now};
            } else if (now - a[2] > windowMs[k]) {
                anchor[0] = new double[] {x, z, now};
                anchor[1] = new double[] {x, z, now};
                signal("stuck");
                return;
            }
        }
    }

    @Override
    protected void defineProperties() {
        super.defineProperties();
        defineObsProperty("centralSensor", 0.0);
        defineObsProperty("caught", false);
        defineObsProperty("picked", false);
    }

    // The Khepera's front-left and front-right sensors see what is ahead; its side sensors
    // (left, right) only matter for lateral cylinders and obstacles.
    @Override
    protected SensorKind leftKind() {
        return SensorKind.FRONT_LEFT_DISTANCE;
    }

    @Override
    protected SensorKind rightKind() {
        return SensorKind.FRONT_RIGHT_DISTANCE;
    }

    @Override
    protected boolean clearAhead() {
        return getObsProperty("centralSensor").doubleValue() < SAFE;
    }

    private boolean red(int section) {
        return isRed(rgb[3 * section], rgb[3 * section + 1], rgb[3 * section + 2]);
    }

    /** The thesis' red test (Chapter 4 §2.2: red over twice green and blue) for a section mean or a pixel; bright enough: ours. */
    static boolean isRed(int r, int g, int b) {
        return r > 40 && r > RED_RATIO * g && r > RED_RATIO * b;
    }

    @Override
    protected void onReading(SensorInfo info, SensorKind kind) {
        forgetStaleLateral(); // before any reading consults it: sections, far sight, lateral obstacles
        switch (kind) {
            case CAMERA_SECTIONS:
                int[] v = info.getIntValues();
                if (v.length == 9) {
                    rgb = v;
                }
                if (lateralCylinder != null && red(1)) {
                    lateralCylinder = null; // turned towards it: now it is ahead
                    signal("cylinderBeyond");
                } else if (lateralCylinder == null && !stopDistance && !holding && !cylinderSignalled
                        && !red(1) && (red(0) || red(2))) {
                    lateralCylinder = red(0) ? "left" : "right";
                    lateralSinceMs = simTimeMs();
                    signal(red(0) ? "cylinderLeft" : "cylinderRight");
                }
                break;
            case CENTRAL_DISTANCE:
                if (stopDistance) {
                    break;
                }
                double central = info.getVal();
                getObsProperty("centralSensor").updateValue(central);
                if (central > VERY_CLOSE && !holding) {
                    if (red(1)) {
                        if (!cylinderSignalled) {
                            cylinderSignalled = true;
                            lateralCylinder = null;
                            signal("cylinderDetected");
                        }
                    } else if (!getObsProperty("obstacle").booleanValue()) {
                        getObsProperty("obstacle").updateValue(true);
                    }
                } else if (central < SAFE) {
                    cylinderSignalled = false;
                }
                break;
            case LEFT_DISTANCE:
            case RIGHT_DISTANCE:
                lateral(info.getVal(), kind == SensorKind.LEFT_DISTANCE ? "left" : "right");
                break;

            case GPS:
                double[] c = info.getCoord();
                checkProgress(c[0], c[2]);
                if (locating) {
                    getObsProperty("location").updateValues(trunc(c[0]), trunc(c[1]), trunc(c[2]));
                }
                break;
            case COMPASS:
                noteCompass(info.getCoord());
                if (locating) {
                    getObsProperty("orientation").updateValue(Math.round(heading * 10) / 10.0);
                }
                break;
            case CAMERA_IMAGE:
                sight(info);
                break;
            case GRIP_FORCE:
                boolean nowHolding = info.getVal() < HOLD_FORCE;
                if (nowHolding != getObsProperty("caught").booleanValue()) {
                    getObsProperty("caught").updateValue(nowHolding);
                }
                holding = nowHolding;
                break;
            case GRIP_PRESENCE:
                boolean present = info.getVal() > 0.5;
                boolean picked = getObsProperty("picked").booleanValue();
                if (picked && !present) {
                    getObsProperty("picked").updateValue(false);
                    signal("fallen");
                }
                break;
            case GRIPPER_POSITIONS:
                armPosition = info.getDoubleValues()[0];
                if (armPosition < 0.05 && holding && !getObsProperty("picked").booleanValue()) {
                    getObsProperty("picked").updateValue(true);
                } else if (!holding && getObsProperty("picked").booleanValue()) {
                    getObsProperty("picked").updateValue(false);
                }
                break;
            default:
                super.onReading(info, kind);
        }
    }

    private void lateral(double value, String side) {
        if (stopDistance || holding) {
            return;
        }
        if (value > VERY_CLOSE && lateralCylinder == null && lateralSignalled.add(side)) {
            signal("lateralObstacle", side);
        } else if (value < SAFE) {
            lateralSignalled.remove(side);
        }
    }

    /** Opens and lowers the gripper, then closes it on the cylinder (the controller's manoeuvre). */
    @OPERATION
    void catching() {
        send(Command.catching());
    }

    @OPERATION
    void arm_up() {
        send(Command.armUp());
    }

    @OPERATION
    void arm_down() {
        send(Command.armDown());
    }

    @OPERATION
    void open_grip() {
        send(Command.openGrip());
    }

    @OPERATION
    void close_grip(double target) {
        send(Command.closeGrip(target));
    }

    /** Lowers the arm, opens the gripper and raises the arm again. */
    @OPERATION
    void putDown() {
        send(Command.of(CommandCode.PUT_DOWN));
    }
}
