package jacabot.sim.world;

import jacabot.sim.geom.Rgb;

/** An upright cylinder, the object the robot picks: centre (x, z), radius and height in metres, mass in kg. */
public record CylinderSpec(String id, double x, double z, double radius, double height, double mass, Rgb color) {
}
