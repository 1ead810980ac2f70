package jacabot.sim.device;

/**
 * The two driven wheels, after Webots' {@code DifferentialWheels}: speeds in speed units, clamped
 * to ±{@link #getMaxSpeed()}; one unit is {@link #getSpeedUnit()} m/s of wheel rim speed. Setters
 * return at once; the world applies the speeds on the next physics step (kinematically: the robot's
 * velocity is set from them, and contacts still stop it).
 */
public final class DifferentialWheels implements Device {
    private final String name;
    private final double maxSpeed, speedUnit, axleLength;
    private double left, right;

    public DifferentialWheels(String name, double maxSpeed, double speedUnit, double axleLength) {
        this.name = name;
        this.maxSpeed = maxSpeed;
        this.speedUnit = speedUnit;
        this.axleLength = axleLength;
    }

    @Override
    public String name() {
        return name;
    }

    /** Sets both wheel speeds (speed units), clamped to ±max; NaN counts as 0. */
    public void setSpeeds(double leftSpeed, double rightSpeed) {
        left = clamp(leftSpeed);
        right = clamp(rightSpeed);
    }

    /** Webots' name for {@link #setSpeeds}. */
    public void setSpeed(double leftSpeed, double rightSpeed) {
        setSpeeds(leftSpeed, rightSpeed);
    }

    private double clamp(double v) {
        if (Double.isNaN(v)) {
            return 0;
        }
        return Math.max(-maxSpeed, Math.min(maxSpeed, v));
    }

    public double getLeftSpeed() {
        return left;
    }

    public double getRightSpeed() {
        return right;
    }

    public double getMaxSpeed() {
        return maxSpeed;
    }

    /** {@return metres per second of one speed unit} */
    public double getSpeedUnit() {
        return speedUnit;
    }

    /** {@return the distance between the wheels in metres} */
    public double getAxleLength() {
        return axleLength;
    }

    /** {@return the forward speed in m/s the current wheel speeds give} */
    public double linearVelocity() {
        return (left + right) / 2 * speedUnit;
    }

    /** {@return the turn rate in degrees/s, positive clockwise (towards the right), the bearing's sense} */
    public double turnRate() {
        return Math.toDegrees((left - right) * speedUnit / axleLength);
    }
}
