package jacabot.sim.geom;

/**
 * A point or vector on the floor plane, in metres. Webots' ground plane is x-z (y is up), so the
 * components are named {@code x} and {@code z}. North is +x and east is +z: seen from above with
 * north up, +z points right.
 */
public record Vec2(double x, double z) {
    /** The origin. */
    public static final Vec2 ZERO = new Vec2(0, 0);

    /** {@return the unit vector of a compass bearing (degrees, 0 = north (+x), 90 = east (+z))} */
    public static Vec2 ofBearing(double bearingDeg) {
        double r = Math.toRadians(bearingDeg);
        return new Vec2(Math.cos(r), Math.sin(r));
    }

    /** {@return this plus {@code o}} */
    public Vec2 plus(Vec2 o) {
        return new Vec2(x + o.x, z + o.z);
    }

    /** {@return this minus {@code o}} */
    public Vec2 minus(Vec2 o) {
        return new Vec2(x - o.x, z - o.z);
    }

    /** {@return this scaled by {@code k}} */
    public Vec2 times(double k) {
        return new Vec2(x * k, z * k);
    }

    /** {@return the Euclidean length} */
    public double length() {
        return Math.hypot(x, z);
    }

    /** {@return the distance to {@code o}} */
    public double distanceTo(Vec2 o) {
        return Math.hypot(x - o.x, z - o.z);
    }

    /** {@return the dot product} */
    public double dot(Vec2 o) {
        return x * o.x + z * o.z;
    }
}
