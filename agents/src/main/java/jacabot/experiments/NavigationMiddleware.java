package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.cartago.OpFeedbackParam;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;

/**
 * Experiment 3's middleware (thesis Chapter 4 §3.2): {@code location(X,Y,Z)} from the GPS
 * (truncated to centimetres, as the thesis does), {@code orientation(O)} from the compass (degrees
 * from north, clockwise: the thesis' {@code convertBearing}); signals {@code targetReached} when the
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

    @Override
    protected void defineProperties() {
        super.defineProperties();
        defineObsProperty("location", 0.0, 0.0, 0.0);
        defineObsProperty("orientation", 0.0);
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

    /** Watch for the robot leaving the storage area ({@code outOfStorageArea}). */
    @OPERATION
    void waitExit() {
        waitingExit = true;
    }

    @Override
    protected void onReading(SensorInfo info, SensorKind kind) {
        switch (kind) {
            case GPS:
                double[] c = info.getCoord();
                checkProgress(c[0], c[2]);
                double x = trunc(c[0]);
                double y = trunc(c[1]);
                double z = trunc(c[2]);
                getObsProperty("location").updateValues(x, y, z);
                checkTarget(c[0], c[2]);
                checkStorage(c[0], c[2]);
                break;
            case COMPASS:
                double[] n = info.getCoord();
                noteCompass(n);
                getObsProperty("orientation").updateValue(Math.round(orientation(n) * 10) / 10.0);
                break;
            default:
                super.onReading(info, kind);
        }
    }

    private static double trunc(double v) {
        return Math.floor(v * 100) / 100.0;
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
