package jacabot.sim.geom;

/**
 * A position on the floor plane (metres) and a heading as a compass bearing in degrees:
 * 0 = north (+x), 90 = east (+z), increasing clockwise seen from above; always in [0, 360).
 */
public record Pose(double x, double z, double heading) {
    /** Normalises the heading into [0, 360). */
    public Pose {
        heading = normalize(heading);
    }

    /** {@return the position} */
    public Vec2 position() {
        return new Vec2(x, z);
    }

    /** {@return the unit vector the pose faces} */
    public Vec2 forward() {
        return Vec2.ofBearing(heading);
    }

    /** {@return a bearing in degrees brought into [0, 360)} */
    public static double normalize(double degrees) {
        double d = degrees % 360.0;
        if (d < 0) {
            d += 360.0;
        }
        return d == 360.0 ? 0.0 : d;
    }
}
