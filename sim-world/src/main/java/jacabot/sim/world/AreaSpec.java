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
        return p.distanceTo(centre()) <= radius;
    }
}
