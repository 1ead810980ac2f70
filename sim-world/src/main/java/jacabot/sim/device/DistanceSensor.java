package jacabot.sim.device;

import jacabot.sim.geom.Pose;
import java.util.List;
import java.util.Random;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * An infra-red distance sensor, after Webots' {@code DistanceSensor}. It casts {@code rays} rays
 * spread evenly over its aperture (one ray along the axis when {@code rays == 1}). Each ray that
 * meets an object at distance d gives {@code reflectance × table.output(d)}, where the
 * reflectance of walls, boxes and cylinders is the red channel of their colour / 255 (infra-red light
 * is reflected like red light: white and red objects fully, dark ones little) and that of a robot
 * its model's shell reflectance ({@code RobotModel.shellReflectance}); a ray that meets nothing gives
 * {@code table.output(range)}. The reading is the average of the rays weighted by
 * {@code exp(-(angle / aperture)^2)}, plus a Gaussian noise of standard deviation
 * {@code noise(d) × value} from the sensor's own seeded generator.
 */
public final class DistanceSensor extends Sensor {
    private final LookupTable table;
    private final int rays;
    private final double aperture;
    private final Supplier<Pose> mount;
    private final RayCaster caster;
    private final Random noise; // null: no noise
    private double value = Double.NaN;

    /**
     * @param aperture the cone's full width in degrees
     * @param mount    the sensor's pose in the world (position and axis bearing)
     * @param noise    the noise generator, or null for none
     */
    public DistanceSensor(String name, LongSupplier clock, LookupTable table, int rays, double aperture,
                          Supplier<Pose> mount, RayCaster caster, Random noise) {
        super(name, clock);
        if (rays < 1) {
            throw new IllegalArgumentException("a distance sensor needs at least one ray");
        }
        this.table = table;
        this.rays = rays;
        this.aperture = aperture;
        this.mount = mount;
        this.caster = caster;
        this.noise = noise;
    }

    /** {@return the last reading (raw value), NaN before the first period or when disabled} */
    public double getValue() {
        return hasValue() ? value : Double.NaN;
    }

    /** {@return the lookup table} */
    public LookupTable getLookupTable() {
        return table;
    }

    /** {@return the smallest value of the table} */
    public double getMinValue() {
        return table.minOutput();
    }

    /** {@return the largest value of the table} */
    public double getMaxValue() {
        return table.maxOutput();
    }

    /** {@return the range in metres (the table's last input)} */
    public double getRange() {
        return table.maxInput();
    }

    /** {@return the aperture in degrees} */
    public double getAperture() {
        return aperture;
    }

    /** {@return the sensor's current pose in the world} */
    public Pose pose() {
        return mount.get();
    }

    @Override
    protected void sample() {
        double[] m = measure();
        double v = m[0];
        if (noise != null && m[1] > 0) {
            v += v * m[1] * noise.nextGaussian();
        }
        value = v;
    }

    /** {@return the noiseless value the sensor would read now} */
    public double measureNoiseless() {
        return measure()[0];
    }

    /** {value, noise fraction}. */
    private double[] measure() {
        Pose p = mount.get();
        double range = table.maxInput();
        double sum = 0, noiseSum = 0, weights = 0;
        double[] bearings = new double[rays];
        for (int i = 0; i < rays; i++) {
            bearings[i] = p.heading() + (rays == 1 ? 0 : -aperture / 2 + i * aperture / (rays - 1));
        }
        // the rays share one broad phase: the few objects this close are found once, not per ray
        List<List<RayHit>> fan = rays == 1 ? List.of(caster.castAll(p.position(), bearings[0], range))
                : caster.castFan(p.position(), bearings, range);
        for (int i = 0; i < rays; i++) {
            double angle = rays == 1 ? 0 : -aperture / 2 + i * aperture / (rays - 1);
            double w = rays == 1 ? 1 : Math.exp(-(angle / aperture) * (angle / aperture));
            RayHit hit = fan.get(i).isEmpty() ? null : fan.get(i).get(0);
            double d = hit == null ? range : hit.distance();
            double reflectance = hit == null ? 1.0 : hit.reflectance();
            sum += w * reflectance * table.output(d);
            noiseSum += w * table.noise(d);
            weights += w;
        }
        return new double[] {sum / weights, noiseSum / weights};
    }
}
