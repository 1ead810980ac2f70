package jacabot.sim.device;

import jacabot.sim.geom.Pose;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * A compass, after Webots' {@code Compass}. {@link #getBearing()} is the robot's heading in degrees
 * from north (+x), clockwise seen from above, in [0, 360). {@link #getValues()} is the north
 * vector as Webots gives it, {cos b, 0, -sin b} for bearing b, chosen so that the thesis'
 * {@code convertBearing} ({@code (atan2(v[0], v[2]) - π/2) × 180/π}, plus 360 if negative) returns b.
 */
public final class Compass extends Sensor {
    private final Supplier<Pose> pose;
    private double bearing;

    public Compass(String name, LongSupplier clock, Supplier<Pose> pose) {
        super(name, clock);
        this.pose = pose;
    }

    /** {@return the north vector {x, y, z}; NaNs before the first period} */
    public double[] getValues() {
        if (!hasValue()) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
        double r = Math.toRadians(bearing);
        return new double[] {Math.cos(r), 0.0, -Math.sin(r)};
    }

    /** {@return the bearing in degrees, 0 = north, 90 = east; NaN before the first period} */
    public double getBearing() {
        return hasValue() ? bearing : Double.NaN;
    }

    @Override
    protected void sample() {
        bearing = pose.get().heading();
    }
}
