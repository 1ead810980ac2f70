package jacabot.sim.world;

import jacabot.sim.geom.Vec2;

/**
 * The outline of an object on the floor, for start-up checks (inside the arena, no overlap):
 * a circle, or a rectangle turned by a heading. Plain geometry, no physics engine.
 */
public final class Footprint {
    private final Vec2 centre;
    private final double radius;      // > 0 for a circle
    private final double halfX, halfZ; // for a rectangle
    private final Vec2 axisX, axisZ;   // the rectangle's own axes, unit vectors

    private Footprint(Vec2 centre, double radius, double halfX, double halfZ, double heading) {
        this.centre = centre;
        this.radius = radius;
        this.halfX = halfX;
        this.halfZ = halfZ;
        this.axisX = Vec2.ofBearing(heading);
        this.axisZ = Vec2.ofBearing(heading + 90);
    }

    /** {@return a circle} */
    public static Footprint circle(double x, double z, double radius) {
        return new Footprint(new Vec2(x, z), radius, 0, 0, 0);
    }

    /** {@return a rectangle of full sizes sizeX × sizeZ turned by heading degrees} */
    public static Footprint rectangle(double x, double z, double sizeX, double sizeZ, double heading) {
        return new Footprint(new Vec2(x, z), 0, sizeX / 2, sizeZ / 2, heading);
    }

    private boolean isCircle() {
        return radius > 0;
    }

    /** {@return whether the outline lies within x in [-hx, hx], z in [-hz, hz]} */
    public boolean inside(double hx, double hz) {
        double ex, ez;
        if (isCircle()) {
            ex = radius;
            ez = radius;
        } else {
            ex = Math.abs(axisX.x()) * halfX + Math.abs(axisZ.x()) * halfZ;
            ez = Math.abs(axisX.z()) * halfX + Math.abs(axisZ.z()) * halfZ;
        }
        double eps = 1e-9;
        return centre.x() - ex >= -hx - eps && centre.x() + ex <= hx + eps
                && centre.z() - ez >= -hz - eps && centre.z() + ez <= hz + eps;
    }

    /** {@return whether the two outlines overlap by more than a micrometre (touching is allowed)} */
    public boolean overlaps(Footprint o) {
        double eps = 1e-6;
        if (isCircle() && o.isCircle()) {
            return centre.distanceTo(o.centre) < radius + o.radius - eps;
        }
        if (isCircle()) {
            return o.distanceToRect(centre) < radius - eps;
        }
        if (o.isCircle()) {
            return distanceToRect(o.centre) < o.radius - eps;
        }
        Vec2[] axes = {axisX, axisZ, o.axisX, o.axisZ};
        for (Vec2 a : axes) {
            double d = Math.abs(o.centre.minus(centre).dot(a));
            if (d >= projection(a) + o.projection(a) - eps) {
                return false;
            }
        }
        return true;
    }

    private double projection(Vec2 axis) {
        return halfX * Math.abs(axisX.dot(axis)) + halfZ * Math.abs(axisZ.dot(axis));
    }

    /** Distance from a point to this rectangle (0 inside). */
    private double distanceToRect(Vec2 p) {
        Vec2 d = p.minus(centre);
        double u = Math.max(Math.abs(d.dot(axisX)) - halfX, 0);
        double v = Math.max(Math.abs(d.dot(axisZ)) - halfZ, 0);
        return Math.hypot(u, v);
    }
}
