package jacabot.sim.world;

import jacabot.sim.geom.Rgb;

/**
 * A rectangular block (a wall or a cubic obstacle): centre (x, z) in metres, size along its own
 * x and z axes, heading in degrees (a compass bearing), height in metres, movable or fixed, mass in kg.
 */
public record BoxSpec(String id, double x, double z, double sizeX, double sizeZ, double heading, double height,
                      boolean movable, double mass, Rgb color) {
}
