package jacabot.experiments;

import jacabot.cartago.OPERATION;
import jacabot.robot.link.SensorInfo;
import jacabot.robot.link.SensorKind;

/**
 * Experiment 4's middleware (thesis Chapter 4 §4.1, Appendix B): {@code battery(B)} in joules and
 * the {@code lowBattery} signal while the energy is under {@value #LOW_BATTERY} (the thesis'
 * {@code battery < 480 & battery > 0}), the {@code charged} signal when, after a low battery, the
 * energy is back to {@value #CHARGED} J (ours, see suspend-resume.asl), and {@code mark}, which
 * records where the running task was suspended, or {@code mark(X, Y, Z)}, the point the robot comes
 * back to (ours: where the low-battery episode began).
 */
public class SuspendResumeMiddleware extends NavigationMiddleware {
    static final double LOW_BATTERY = 480;
    /** The level at which {@code charged} is signalled (ours: the thesis waits 3 s at the charger). */
    static final double CHARGED = 900;
    // (not in the thesis) the agent may set both levels from its beliefs (batteryLevels)
    private double low = LOW_BATTERY;
    private double charged = CHARGED;
    private boolean chargedSignalled = true;
    private double[] marked;

    @Override
    protected void defineProperties() {
        super.defineProperties();
        defineObsProperty("battery", 0.0);
    }

    @Override
    protected void onReading(SensorInfo info, SensorKind kind) {
        if (kind == SensorKind.BATTERY) {
            double battery = Math.round(info.getVal() * 10) / 10.0;
            getObsProperty("battery").updateValue(battery);
            if (battery < low && battery > 0) {
                signal("lowBattery");
            }
            if (battery >= charged && !chargedSignalled) {
                chargedSignalled = true;
                signal("charged");
            } else if (battery < low) {
                chargedSignalled = false;
            }
        } else {
            super.onReading(info, kind);
        }
    }

    /** Sets the levels of {@code lowBattery} and {@code charged} (joules). */
    @OPERATION
    void batteryLevels(double lowLevel, double chargedLevel) {
        low = lowLevel;
        charged = chargedLevel;
    }

    /** Records the current location (x, z) and orientation (the agent keeps its own copy as beliefs). */
    @OPERATION
    void mark() {
        var location = getObsProperty("location");
        mark(location.doubleValue(0), location.doubleValue(1), location.doubleValue(2));
    }

    /**
     * Records the point {@code (x, y, z)} the robot comes back to and the current orientation (not in the
     * thesis: recharge-trip.asl's way back ends where the low-battery episode began, which a trip put off by
     * a put-down begins later and elsewhere).
     */
    @OPERATION
    void mark(double x, double y, double z) {
        marked = new double[] {x, z, getObsProperty("orientation").doubleValue()};
        log("marked at (" + x + ", " + z + "), heading " + marked[2]);
    }

    /** {@return the last point marked, {x, z, orientation}, or null} */
    double[] marked() {
        return marked == null ? null : marked.clone();
    }
}
