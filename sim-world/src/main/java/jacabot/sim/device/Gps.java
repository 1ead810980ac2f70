package jacabot.sim.device;

import jacabot.sim.geom.Pose;
import java.util.Random;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * A GPS, after Webots' {@code GPS}: {@code getValues()} is {x, y, z} in metres, y being the
 * height of the device (0 on our flat floor). Optional Gaussian noise of standard deviation
 * {@code noise} metres on x and z, from the device's own seeded generator.
 */
public final class Gps extends Sensor {
    private final Supplier<Pose> pose;
    private final double noise;
    private final Random random;
    private double[] values;

    /** @param random the noise generator (unused when {@code noise == 0}) */
    public Gps(String name, LongSupplier clock, Supplier<Pose> pose, double noise, Random random) {
        super(name, clock);
        this.pose = pose;
        this.noise = noise;
        this.random = random;
    }

    /** {@return {x, y, z} in metres; NaNs before the first period} */
    public double[] getValues() {
        return hasValue() ? values.clone() : new double[] {Double.NaN, Double.NaN, Double.NaN};
    }

    @Override
    protected void sample() {
        Pose p = pose.get();
        double x = p.x(), z = p.z();
        if (noise > 0) {
            x += noise * random.nextGaussian();
            z += noise * random.nextGaussian();
        }
        values = new double[] {x, 0.0, z};
    }
}
