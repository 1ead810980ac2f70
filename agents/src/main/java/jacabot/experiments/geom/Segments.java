package jacabot.experiments.geom;

/** The distance between two line segments of the floor (a point is a segment of no length). */
public final class Segments {
    private Segments() {
    }

    /** {@return the least distance between segment (ax, az)-(bx, bz) and segment (cx, cz)-(dx, dz)} */
    public static double distance(double ax, double az, double bx, double bz, double cx, double cz, double dx, double dz) {
        if (cross(ax, az, bx, bz, cx, cz, dx, dz)) {
            return 0;
        }
        return Math.min(Math.min(toSegment(ax, az, cx, cz, dx, dz), toSegment(bx, bz, cx, cz, dx, dz)),
                Math.min(toSegment(cx, cz, ax, az, bx, bz), toSegment(dx, dz, ax, az, bx, bz)));
    }

    /** {@return the distance from (px, pz) to segment (ax, az)-(bx, bz)} */
    public static double toSegment(double px, double pz, double ax, double az, double bx, double bz) {
        double ux = bx - ax, uz = bz - az;
        double len2 = ux * ux + uz * uz;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * ux + (pz - az) * uz) / len2));
        return Math.hypot(px - (ax + t * ux), pz - (az + t * uz));
    }

    /** Proper crossings only: touching and collinear segments are measured by their ends. */
    private static boolean cross(double ax, double az, double bx, double bz, double cx, double cz, double dx, double dz) {
        double d1 = side(cx, cz, dx, dz, ax, az), d2 = side(cx, cz, dx, dz, bx, bz);
        double d3 = side(ax, az, bx, bz, cx, cz), d4 = side(ax, az, bx, bz, dx, dz);
        return d1 * d2 < 0 && d3 * d4 < 0;
    }

    private static double side(double ax, double az, double bx, double bz, double px, double pz) {
        return (bx - ax) * (pz - az) - (bz - az) * (px - ax);
    }
}
