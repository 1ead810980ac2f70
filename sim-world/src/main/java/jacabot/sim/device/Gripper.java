package jacabot.sim.device;

import java.util.function.LongSupplier;

/**
 * The Khepera gripper: an arm that goes up and down and two fingers that open and close, each
 * movement taking simulated time ({@code armTime}, {@code gripTime} seconds for a full stroke).
 * Positions: arm 0 = up … 1 = down, grip 0 = open … 1 = closed. When the fingers finish closing
 * with the arm down and a cylinder between them, the cylinder is grasped; opening the fingers
 * sets it down. Two sub-sensors use the Webots triad: force feedback ({@code -gripForce} newtons
 * while a cylinder is held, 0 otherwise, as the thesis' {@code -500 < force < -5} test expects) and
 * presence (1 when a cylinder is held or lies between the lowered fingers, else 0).
 */
public final class Gripper implements Device {
    private final String name;
    private final double armTime, gripTime, gripForce;
    private final GraspHost host;
    private final Sampling forceSampling, presenceSampling;
    private double arm, armTarget, grip, gripTarget;
    private String held;
    private double force, presence;

    public Gripper(String name, LongSupplier clock, double armTime, double gripTime, double gripForce, GraspHost host) {
        this.name = name;
        this.armTime = armTime;
        this.gripTime = gripTime;
        this.gripForce = gripForce;
        this.host = host;
        this.forceSampling = new Sampling(clock);
        this.presenceSampling = new Sampling(clock);
    }

    @Override
    public String name() {
        return name;
    }

    /** Starts lowering the arm. */
    public void armDown() {
        armTarget = 1;
    }

    /** Starts raising the arm. */
    public void armUp() {
        armTarget = 0;
    }

    /** Starts opening the fingers (and so lets a held cylinder go). */
    public void openGrip() {
        gripTarget = 0;
    }

    /** Starts closing the fingers. */
    public void closeGrip() {
        gripTarget = 1;
    }

    /** {@return the arm position, 0 = up … 1 = down} */
    public double getArmPosition() {
        return arm;
    }

    /** {@return the finger position, 0 = open … 1 = closed} */
    public double getGripPosition() {
        return grip;
    }

    public boolean isArmUp() {
        return arm == 0;
    }

    public boolean isArmDown() {
        return arm == 1;
    }

    /** {@return the id of the cylinder held, or null (ground truth, for supervisors and tests)} */
    public String heldObject() {
        return held;
    }

    public void enableForceFeedback(int samplingPeriodMs) {
        forceSampling.enable(samplingPeriodMs);
    }

    public void disableForceFeedback() {
        forceSampling.disable();
    }

    public int getForceFeedbackSamplingPeriod() {
        return forceSampling.period();
    }

    /** {@return the grip force in newtons (negative while squeezing a cylinder), NaN before the first period} */
    public double getForceFeedback() {
        return forceSampling.ready() ? force : Double.NaN;
    }

    public void enablePresence(int samplingPeriodMs) {
        presenceSampling.enable(samplingPeriodMs);
    }

    public void disablePresence() {
        presenceSampling.disable();
    }

    public int getPresenceSamplingPeriod() {
        return presenceSampling.period();
    }

    /** {@return 1 when an object is between the fingers, else 0; NaN before the first period} */
    public double getPresence() {
        return presenceSampling.ready() ? presence : Double.NaN;
    }

    /** Knocks the held cylinder out of the fingers; {@return whether one was held} */
    public boolean knock() {
        if (held == null) {
            return false;
        }
        String id = held;
        held = null;
        host.release(id, true);
        return true;
    }

    /** Forgets the held cylinder without placing it (it was removed from the world). */
    public void forget(String id) {
        if (id.equals(held)) {
            held = null;
        }
    }

    /** Called by the world every physics step of {@code dt} seconds: moves arm and fingers. */
    public void step(double dt) {
        arm = approach(arm, armTarget, dt / armTime);
        double before = grip;
        grip = approach(grip, gripTarget, dt / gripTime);
        if (held != null && grip < before) {
            String id = held;
            held = null;
            host.release(id, false);
        }
        if (held == null && grip == 1 && before < 1 && arm == 1) {
            String id = host.graspable();
            if (id != null) {
                held = id;
                host.attach(id);
            }
        }
    }

    /** Called by the world after each physics step: takes the sub-sensors' readings when due. */
    public void tick(long nowMs) {
        if (forceSampling.due(nowMs)) {
            force = held != null ? -gripForce : 0.0;
        }
        if (presenceSampling.due(nowMs)) {
            presence = held != null || (arm == 1 && grip < 1 && host.graspable() != null) ? 1.0 : 0.0;
        }
    }

    private static double approach(double value, double target, double step) {
        if (value < target) {
            return Math.min(target, value + step);
        }
        return Math.max(target, value - step);
    }
}
