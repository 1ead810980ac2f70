package jacabot.sim.device;

import jacabot.sim.geom.Rgb;

/**
 * What a ray met: the distance along the floor in metres, the surface colour, the object's height
 * in metres and its id.
 */
public record RayHit(double distance, Rgb color, double height, String objectId) {
}
