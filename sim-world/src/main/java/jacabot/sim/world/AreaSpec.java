package jacabot.sim.world;

import jacabot.sim.geom.Vec2;

/**
 * A circular floor zone: the storage (gathering) point, or the charger when {@code power > 0}
 * (watts, i.e. joules per second added to a robot's battery while its centre is inside).
 */
public record AreaSpec(double x, double z, double radius, double power) {
    /** {@return the centre} */
    public Vec2 centre() {
        return new Vec2(x, z);
    }

    /** {@return whether a point lies in the zone} */
    public boolean contains(Vec2 p) {
        return contains(p.x(), p.z());
    }

    /**
     * {@return whether the point (x, z) lies in the zone, its distance from the centre at most the radius}:
     * tidy-up's success criterion counts a cylinder as stored by it, and the robot is told of the
     * cylinders its world starts with in the storage area by the same test
     */
    public boolean contains(double x, double z) {
        return Math.hypot(x - this.x, z - this.z) <= radius;
    }
}
