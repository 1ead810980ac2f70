package jacabot.sim.device;

import java.util.function.LongSupplier;

/**
 * A robot's battery and its sensor, after Webots' {@code Robot.battery} field and
 * {@code batterySensorEnable}/{@code batterySensorGetValue}. Energy in joules. The world drains it
 * every physics step by {@code idlePower + motorPower × (|left| + |right|) / (2 × maxSpeed)}
 * watts and recharges it at the charger's power while the robot's centre is on the charger. At 0 the
 * robot's motors stop.
 */
public final class Battery extends Sensor {
    private final double maxEnergy, idlePower, motorPower;
    private double energy;
    private double reading;

    public Battery(String name, LongSupplier clock, double maxEnergy, double initialEnergy, double idlePower, double motorPower) {
        super(name, clock);
        this.maxEnergy = maxEnergy;
        this.energy = Math.max(0, Math.min(maxEnergy, initialEnergy));
        this.idlePower = idlePower;
        this.motorPower = motorPower;
    }

    /** {@return the last reading of the energy in joules, NaN before the first period} */
    public double getValue() {
        return hasValue() ? reading : Double.NaN;
    }

    /** {@return the maximum energy in joules} */
    public double getMaxEnergy() {
        return maxEnergy;
    }

    /** {@return the idle consumption in watts} */
    public double getIdlePower() {
        return idlePower;
    }

    /** {@return the consumption of both motors at full speed, in watts} */
    public double getMotorPower() {
        return motorPower;
    }

    /** {@return the current energy in joules (the true value, not a reading)} */
    public double energy() {
        return energy;
    }

    /** {@return whether the battery is empty} */
    public boolean isEmpty() {
        return energy <= 0;
    }

    /** Removes energy (clamped at 0). */
    public void drain(double joules) {
        energy = Math.max(0, energy - joules);
    }

    /** Adds energy (clamped at the maximum). */
    public void charge(double joules) {
        energy = Math.min(maxEnergy, energy + joules);
    }

    /** Sets the energy (clamped to [0, max]). */
    public void setEnergy(double joules) {
        energy = Math.max(0, Math.min(maxEnergy, joules));
    }

    /** {@return the power drawn in watts for wheel speeds given as fractions of the maximum} */
    public double power(double leftFraction, double rightFraction) {
        return idlePower + motorPower * (Math.abs(leftFraction) + Math.abs(rightFraction)) / 2;
    }

    @Override
    protected void sample() {
        reading = energy;
    }
}
