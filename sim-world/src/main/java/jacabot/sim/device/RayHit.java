package jacabot.sim.device;

import jacabot.sim.geom.Rgb;

/**
 * What a ray met: the distance along the floor in metres, the surface colour, the object's height
 * in metres, its id, and the share of infra-red light its surface returns (0..1; see
 * {@link DistanceSensor}).
 */
public record RayHit(double distance, Rgb color, double height, String objectId, double reflectance) {
    /** {@return the infra-red reflectance of a painted surface: its red channel / 255 (infra-red is reflected as red light is)} */
    public static double reflectanceOf(Rgb color) {
        return color.red() / 255.0;
    }
}
